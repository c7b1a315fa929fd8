/*
** interrupt.h - Ctrl-C as a request, not a kill.  The handler only sets
** a flag; the step loop polls it between steps, and running Lua code is
** stopped through a debug hook (as the lua prompt does).
*/
#ifndef mvmpm_interrupt_h
#define mvmpm_interrupt_h

#include <signal.h>
#include "lua.h"

extern volatile sig_atomic_t interrupt_flag;

/* install the SIGINT handler; L (may be NULL) gets the stop hook, which
** raises "interrupted!" at the next Lua instruction (C functions are left
** to poll).  The handler is one-shot: a second Ctrl-C before the first
** is honoured kills the program (the way out of C code that never polls) */
void interrupt_install(lua_State *L);
/* restore the default action (a second Ctrl-C then kills) and disarm
** the stop hook if it never fired; the flag is left for the caller */
void interrupt_uninstall(void);
static inline int interrupt_pending(void) { return interrupt_flag != 0; }
static inline void interrupt_clear(void) { interrupt_flag = 0; }

#endif
