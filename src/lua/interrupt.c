/*
** interrupt.c - Ctrl-C as a request to stop, not a kill.
** The SIGINT handler does only what is safe in a handler: it sets
** interrupt_flag, which C loops poll between steps, and, when a Lua
** state was given, arms a debug hook (lua_sethook may be called from a
** signal handler) that stops running Lua code at its next instruction.
** The handler is one-shot: a second Ctrl-C before the first one is
** honoured gets the default action and ends the program, the way out of
** C code that never polls.
*/
#include <signal.h>
#include <stddef.h>

#include "lua.h"

#include "interrupt.h"

volatile sig_atomic_t interrupt_flag = 0;

/* state the handler arms; changed only while no handler is installed */
static lua_State *target = NULL;

#define STOPMASK (LUA_MASKCALL | LUA_MASKRET | LUA_MASKLINE | LUA_MASKCOUNT)


/*
** The hook armed by the handler.  Inside a C function it waits: that C
** code polls interrupt_pending() and raises its own error, and an error
** raised here (say on the call of the message handler that error
** triggers) would only replace it.  Any Lua instruction stops.
*/
static void stop(lua_State *L, lua_Debug *ar) {
  if (ar->event != LUA_HOOKCOUNT && ar->event != LUA_HOOKLINE &&
      lua_getinfo(L, "S", ar) && ar->what[0] == 'C')
    return;
  lua_sethook(L, NULL, 0, 0);  /* once: error handlers must run */
  lua_pushliteral(L, "interrupted!");
  lua_error(L);
}


static void onint(int sig) {
  (void)sig;
  interrupt_flag = 1;
  if (target != NULL)
    lua_sethook(target, stop, STOPMASK, 1);
}


static void setaction(void (*handler)(int), int flags) {
  struct sigaction sa;
  sa.sa_handler = handler;
  sa.sa_flags = flags;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, NULL);
}


/*
** No SA_RESTART: a blocking read (the prompt, io.read) must return
** EINTR so that Ctrl-C reaches the code waiting in it.
*/
void interrupt_install(lua_State *L) {
  target = L;
  setaction(onint, SA_RESETHAND);
}


/* Also disarms the hook if it never fired (a C function took the stop),
** so it cannot stop the next command. */
void interrupt_uninstall(void) {
  setaction(SIG_DFL, 0);
  if (target != NULL && lua_gethook(target) == stop)
    lua_sethook(target, NULL, 0, 0);
  target = NULL;
}
