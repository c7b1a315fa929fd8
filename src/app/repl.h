/*
** repl.h - the interactive prompt, behaving like the lua prompt:
** expressions print their values, incomplete input continues on a
** second prompt, errors print and the session goes on; line editing and
** history through libedit.
*/
#ifndef mvmpm_repl_h
#define mvmpm_repl_h

#include "lua.h"

/*
** Read-eval-print on L until end of input (Ctrl-D); 0, or 1 if the loop
** itself failed (out of memory; message printed).  On a terminal, line
** editing and history (kept in histfile unless NULL; created if missing)
** come from libedit; otherwise plain lines are read and no prompt is
** printed.  Each input runs between interrupt_install(L) and
** interrupt_uninstall(): Ctrl-C stops it and the prompt comes back.
** L's stack is left as found.
*/
int repl_run(lua_State *L, const char *histfile);

#endif
