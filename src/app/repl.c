/*
** repl.c - the interactive prompt, working like the stand-alone lua
** prompt: a line is first tried as an expression ("return <line>") so
** that its values print; otherwise as a statement, continuing on the
** second prompt while the chunk is incomplete.  Errors print with a
** traceback and the session goes on.  On a terminal, lines come from
** libedit (line editing, history); otherwise plain lines are read and
** no prompt is printed, so piped input gives just the results.
*/
#include <errno.h>
#include <limits.h>
#include <locale.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <wchar.h>

#include <editline/readline.h>

#include "lua.h"
#include "lauxlib.h"

#include "interrupt.h"
#include "repl.h"

#define PROMPT    "mvmpm> "
#define PROMPT2   "    >> "
#define CHUNKNAME "=stdin"
#define EOFMARK   "<eof>"     /* a syntax error here means "go on" */
#define HISTMAX   1000        /* history entries kept */

/* what loadinput gives besides a load status */
enum { R_EOF = -1, R_CANCEL = -2 };

static int tty;               /* reading a terminal through libedit */
static const char *histfile;  /* NULL: history not saved */
static char *lastline;        /* last history entry, to skip repeats */
static char *pipebuf;         /* getline buffer for non-terminal input */
static size_t pipesize;


/* A global without metamethods, so that nothing here can raise. */
static int rawglobal(lua_State *L, const char *name) {
  int t;
  lua_rawgeti(L, LUA_REGISTRYINDEX, LUA_RIDX_GLOBALS);
  lua_pushstring(L, name);
  t = lua_rawget(L, -2);
  lua_remove(L, -2);
  return t;
}


/* ---- history ---- */

static void histopen(void) {
  stifle_history(HISTMAX);
  if (histfile == NULL)
    return;
  if (access(histfile, F_OK) != 0)
    write_history(histfile);  /* create it; errors ignored */
  else
    read_history(histfile);
}


/* Multi-line chunks go in whole, as lua does; saved at once so that a
** crash loses nothing. */
static void histadd(const char *line) {
  if (!tty || line[0] == '\0')
    return;
  if (lastline != NULL && strcmp(lastline, line) == 0)
    return;
  add_history(line);
  free(lastline);
  lastline = strdup(line);
  if (histfile != NULL)
    write_history(histfile);
}


/* ---- reading ---- */

/*
** libedit converts keys through the C library's multibyte functions,
** which in the "C" locale reject every byte above 127: typed non-ASCII
** text would vanish.  So while the prompt runs, a program left in "C"
** reads in the user's character set, or in UTF-8 (what terminals send)
** when that too is "C", as Python does.  Only LC_CTYPE changes, never
** LC_NUMERIC, on which Lua's number syntax depends.
*/
static int plainc(const char *loc) {
  return loc == NULL || strcmp(loc, "C") == 0 || strcmp(loc, "POSIX") == 0;
}


/* The setting to restore afterwards, or NULL. */
static char *widen(void) {
  const char *old = setlocale(LC_CTYPE, NULL);
  char *saved;
  if (old == NULL || !plainc(old) || (saved = strdup(old)) == NULL)
    return NULL;
  if (plainc(setlocale(LC_CTYPE, "")))
    setlocale(LC_CTYPE, "C.UTF-8");
  return saved;
}


static void unwiden(char *saved) {
  if (saved != NULL) {
    setlocale(LC_CTYPE, saved);
    free(saved);
  }
}


/*
** Key reader for libedit.  Its own reader retries a read interrupted
** by a signal, so the first Ctrl-C at the prompt would be lost; this one
** gives up when the flag is set, readline returns, and the prompt starts
** over.  Multibyte characters are decoded as libedit's reader would.
*/
static int getkey(FILE *f) {
  char b[MB_LEN_MAX];
  size_t n = 0;
  int fd = (f != NULL) ? fileno(f) : STDIN_FILENO;
  for (;;) {
    mbstate_t st;
    wchar_t wc;
    size_t r;
    ssize_t got;
    if (interrupt_pending())
      return EOF;  /* Ctrl-C came just before the read */
    got = read(fd, b + n, 1);
    if (got < 0 && errno == EINTR && !interrupt_pending())
      continue;  /* window resized, job resumed */
    if (got <= 0)
      return EOF;  /* end of input, error, or Ctrl-C */
    n++;
    memset(&st, 0, sizeof(st));
    r = mbrtowc(&wc, b, n, &st);
    if (r == (size_t)-2 && n < sizeof(b))
      continue;  /* incomplete character */
    if (r == (size_t)-1 || r == (size_t)-2)
      n = 0;  /* not a character in this locale: dropped */
    else
      return (int)wc;
  }
}


/* Like lua, _PROMPT and _PROMPT2 override the prompts. */
static const char *pushprompt(lua_State *L, int first) {
  const char *p;
  rawglobal(L, first ? "_PROMPT" : "_PROMPT2");
  p = lua_tostring(L, -1);
  if (p == NULL) {
    lua_pop(L, 1);
    p = lua_pushstring(L, first ? PROMPT : PROMPT2);
  }
  return p;
}


/* 1: line pushed; 0: end of input; -1: Ctrl-C, line dropped */
static int readtty(lua_State *L, int first) {
  char *b;
  const char *p = pushprompt(L, first);
  interrupt_install(NULL);
  b = readline(p);
  interrupt_uninstall();
  lua_pop(L, 1);
  if (interrupt_pending()) {
    interrupt_clear();
    free(b);
    fputs("\n", stdout);
    fflush(stdout);
    return -1;
  }
  if (b == NULL) {  /* Ctrl-D: what follows starts on a new line */
    fputs("\n", stdout);
    fflush(stdout);
    return 0;
  }
  lua_pushstring(L, b);
  free(b);
  return 1;
}


/* Whole lines of any length; no prompt. */
static int readpipe(lua_State *L) {
  ssize_t n = getline(&pipebuf, &pipesize, stdin);
  if (n < 0)
    return 0;
  if (n > 0 && pipebuf[n - 1] == '\n')
    n--;
  lua_pushlstring(L, pipebuf, (size_t)n);
  return 1;
}


static int readln(lua_State *L, int first) {
  return tty ? readtty(L, first) : readpipe(L);
}


/* ---- compiling ---- */

static int incomplete(lua_State *L, int status) {
  size_t len, mark = sizeof(EOFMARK) - 1;
  const char *msg;
  if (status != LUA_ERRSYNTAX)
    return 0;
  msg = lua_tolstring(L, -1, &len);
  return len >= mark && strcmp(msg + len - mark, EOFMARK) == 0;
}


/* Line on top; on success the function is pushed above it. */
static int tryreturn(lua_State *L) {
  size_t len;
  const char *code;
  int status;
  lua_pushliteral(L, "return ");
  lua_pushvalue(L, -2);
  lua_concat(L, 2);
  code = lua_tolstring(L, -1, &len);
  status = luaL_loadbuffer(L, code, len, CHUNKNAME);
  lua_remove(L, -2);  /* the "return" text */
  if (status != LUA_OK)
    lua_pop(L, 1);
  return status;
}


/*
** Line on top; compile it as a statement, reading more lines while it
** is incomplete.  Leaves the whole text and above it the function or
** the error message; on Ctrl-C leaves nothing.
*/
static int tryblock(lua_State *L) {
  for (;;) {
    size_t len;
    const char *code = lua_tolstring(L, -1, &len);
    int status = luaL_loadbuffer(L, code, len, CHUNKNAME);
    int more;
    if (!incomplete(L, status))
      return status;
    more = readln(L, 0);
    if (more == 0)
      return status;  /* input ended inside the chunk: report it */
    if (more < 0) {
      lua_pop(L, 2);
      return R_CANCEL;
    }
    lua_remove(L, -2);  /* the message */
    lua_pushliteral(L, "\n");
    lua_insert(L, -2);
    lua_concat(L, 3);
  }
}


/* One input, compiled: the function or error message on top. */
static int loadinput(lua_State *L) {
  int status = readln(L, 1);
  if (status <= 0)
    return status == 0 ? R_EOF : R_CANCEL;
  if ((status = tryreturn(L)) != LUA_OK) {
    status = tryblock(L);
    if (status == R_CANCEL)
      return status;
  }
  histadd(lua_tostring(L, -2));
  lua_remove(L, -2);
  return status;
}


/* ---- running ---- */

static int msghandler(lua_State *L) {
  const char *msg = lua_tostring(L, 1);
  if (msg == NULL) {  /* an error object that is not a string */
    if (luaL_callmeta(L, 1, "__tostring") && lua_type(L, -1) == LUA_TSTRING)
      return 1;
    msg = lua_pushfstring(L, "(error object is a %s value)",
                          luaL_typename(L, 1));
  }
  luaL_traceback(L, L, msg, 1);
  return 1;
}


static int docall(lua_State *L, int narg, int nres) {
  int status;
  int base = lua_gettop(L) - narg;  /* the function */
  lua_pushcfunction(L, msghandler);
  lua_insert(L, base);
  status = lua_pcall(L, narg, nres, base);
  lua_remove(L, base);
  return status;
}


/* Stands in for a missing global 'print'. */
static int putvalues(lua_State *L) {
  int i, n = lua_gettop(L);
  for (i = 1; i <= n; i++) {
    size_t len;
    const char *s = luaL_tolstring(L, i, &len);
    if (i > 1)
      fputc('\t', stdout);
    fwrite(s, 1, len, stdout);
    lua_pop(L, 1);
  }
  fputc('\n', stdout);
  fflush(stdout);
  return 0;
}


/* Print the values above base through the global 'show' (mvmpm.repl's
** readable tables) if there is one, else through 'print'. */
static int show(lua_State *L, int base) {
  int n = lua_gettop(L) - base;
  int status;
  if (n == 0)
    return LUA_OK;
  if (!lua_checkstack(L, LUA_MINSTACK)) {
    lua_settop(L, base);
    lua_pushliteral(L, "too many results to print");
    return LUA_ERRRUN;
  }
  if (rawglobal(L, "show") != LUA_TFUNCTION) {
    lua_pop(L, 1);
    if (rawglobal(L, "print") != LUA_TFUNCTION) {
      lua_pop(L, 1);
      lua_pushcfunction(L, putvalues);
    }
  }
  lua_insert(L, base + 1);
  status = docall(L, n, 0);
  if (status != LUA_OK) {
    lua_pushfstring(L, "error calling 'print' (%s)", lua_tostring(L, -1));
    lua_remove(L, -2);
  }
  return status;
}


static void report(lua_State *L, int status) {
  const char *msg;
  if (status == LUA_OK)
    return;
  msg = lua_tostring(L, -1);
  fflush(stdout);  /* keep results and errors in order */
  fprintf(stderr, "%s\n", msg != NULL ? msg : "(error object is not a string)");
  fflush(stderr);
  lua_pop(L, 1);
}


/*
** Run the function on top and print its results.  Ctrl-C stops it;
** afterwards the flag is cleared, whoever honoured it.
*/
static void evaluate(lua_State *L) {
  int base = lua_gettop(L) - 1;
  int status;
  interrupt_install(L);
  status = docall(L, 0, LUA_MULTRET);
  if (status == LUA_OK)
    status = show(L, base);
  interrupt_uninstall();
  if (interrupt_pending() && tty)
    fputs("\n", stdout);  /* past the "^C" the terminal echoed */
  interrupt_clear();
  report(L, status);
  lua_settop(L, base);
}


/* The loop itself runs protected, so an error outside the user's code
** (out of memory) ends it cleanly instead of panicking. */
static int loop(lua_State *L) {
  int status;
  while ((status = loadinput(L)) != R_EOF) {
    if (status == LUA_OK)
      evaluate(L);
    else if (status != R_CANCEL)
      report(L, status);
  }
  return 0;
}


int repl_run(lua_State *L, const char *hist) {
  int status;
  char *ctype = NULL;
  tty = isatty(STDIN_FILENO);
  histfile = hist;
  if (tty) {
    ctype = widen();  /* before libedit initialises, too */
    rl_readline_name = "mvmpm";  /* for ~/.editrc */
    rl_getc_function = getkey;   /* before libedit initialises */
    histopen();
  }
  lua_pushcfunction(L, loop);
  status = docall(L, 0, 0);
  interrupt_uninstall();
  interrupt_clear();
  report(L, status);
  unwiden(ctype);
  free(lastline);
  lastline = NULL;
  free(pipebuf);
  pipebuf = NULL;
  pipesize = 0;
  return status == LUA_OK ? 0 : 1;
}
