/*
** repl.h - the interactive prompt, behaving like the lua prompt:
** expressions print their values, incomplete input continues on a
** second prompt, errors print and the session goes on; line editing and
** history through libedit.
*/
#ifndef mvmpm_repl_h
#define mvmpm_repl_h

#include "lua.h"

/* Read-eval-print on L until end of input.  histfile may be NULL. */
int repl_run(lua_State *L, const char *histfile);

#endif
