/*
** fuzz_scene.c - libFuzzer driver for the scene loader and the Lua API.
** Each input is a scene's text.  It runs in a sandboxed state (no files
** but under a scratch output directory), text chunks only, with a
** deadline: a debug hook stops Lua code and the step loop's interrupt
** flag stops stepping, so no input can hang the fuzzer.  When the scene
** returns a simulation with particles, a few steps are taken.  Crashes,
** sanitizer reports and leaks are what it looks for; Lua errors are the
** expected outcome of most inputs.
**
**   make fuzz            (clang libFuzzer, seeded with the scenes and
**                         tests/fuzz/seeds; tests/fuzz/run.sh)
**   build-fuzz/fuzz_scene FILE   one input again (a reproducer)
*/
#define _DEFAULT_SOURCE
#include <signal.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/time.h>
#include <time.h>
#include "interrupt.h"
#include "lauxlib.h"
#include "lmvmpm.h"
#include "lualib.h"
#include "sandbox.h"

static double deadline;

static double now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static void hook(lua_State *L, lua_Debug *ar) {
  (void)ar;
  if (now() > deadline) luaL_error(L, "fuzz: time is up");
}

static void alarm_handler(int sig) {
  (void)sig;
  interrupt_flag = 1; /* the step loop polls it between steps */
}

int LLVMFuzzerInitialize(int *argc, char ***argv) {
  (void)argc; (void)argv;
  setenv("MVMPM_MAX_GB", "0.2", 1);
  return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  lua_State *L = luaL_newstate();
  struct itimerval it = {{0, 0}, {0, 500000}};
  struct sigaction sa;
  if (!L) return 0;
  /* a CPU-time alarm of our own: libFuzzer owns SIGALRM */
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = alarm_handler;
  sigaction(SIGVTALRM, &sa, NULL);
  luaL_openlibs(L);
  luaL_requiref(L, "mvmpm", luaopen_mvmpm, 1);
  lua_pop(L, 1);
  sandbox_open(L, "build-fuzz/out");
  interrupt_clear();
  deadline = now() + 0.5;
  lua_sethook(L, hook, LUA_MASKCOUNT, 1000);
  setitimer(ITIMER_VIRTUAL, &it, NULL);
  if (luaL_loadbufferx(L, (const char *)data, size, "=fuzz", "t") == LUA_OK &&
      lua_pcall(L, 0, 1, 0) == LUA_OK && luaL_testudata(L, -1, "mvmpm.sim")) {
    lua_getfield(L, -1, "step");
    lua_pushvalue(L, -2);
    lua_pushinteger(L, 20);
    lua_pcall(L, 2, 0, 0);
  }
  it.it_value.tv_usec = 0;
  setitimer(ITIMER_VIRTUAL, &it, NULL);
  interrupt_clear();
  lua_close(L);
  return 0;
}
