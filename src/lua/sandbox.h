/*
** sandbox.h - running a scene from someone else (mvmpm run --sandbox).
** The scene gets the engine's API and the safe parts of Lua's library;
** it can write files only through the engine's own output, and only
** inside the run's output directory.  What goes:
**   io, debug, package, dofile, loadfile, string.dump, and os except
**   os.clock, os.time and os.date;
**   load takes text only (mode "t"): bytecode can break the VM's checks;
**   require loads only "mvmpm" and "mvmpm.NAME" from the engine's lua/
**   directory (no C modules, no other paths);
**   mvmpm.load (it reads any file) is refused;
**   paths given to sim:snapshot, sim:render, mvmpm.plot and
**   sim:output{dir} must be relative and free of "..": they name files
**   inside the output directory (sandbox_path; a path that starts with
**   the directory itself, as sim.outdir .. "/name" does, names the file
**   below it);
**   mvmpm.open(name) writes a file there (through name.part, renamed
**   when closed), the sandbox's way to write tables;
**   no symbolic link inside the output directory is followed: a file
**   whose path below the root holds one is refused (sandbox_file);
**   the sandbox is recorded in checkpoints and a restart applies it.
** Time and memory are not limited: a scene can still loop forever
** (Ctrl-C stops it) or ask for a huge grid (refused above 16 GB).
*/
#ifndef mvmpm_sandbox_h
#define mvmpm_sandbox_h

#include <stddef.h>
#include "lua.h"

/* restrict L (the standard libraries and the module already open, the
** scene not yet loaded); root is the output directory */
void sandbox_open(lua_State *L, const char *root);
/* 1 if L is restricted */
int sandbox_on(lua_State *L);
/* the file a scene names for writing: path itself outside the sandbox;
** inside, root/path, its directories made; a path that is absolute,
** empty or holds a ".." component raises an error naming what (e.g.
** "snapshot") and the path.  The result lives in buf. */
const char *sandbox_path(lua_State *L, const char *path, const char *what,
                         char *buf, size_t len);
/* sandboxed, a file the engine is about to write (path: the output
** directory, '/', a name below it): an error naming the link if a
** component below the root is a symbolic link.  Unsandboxed, nothing. */
void sandbox_file(lua_State *L, const char *path, const char *what);

#endif
