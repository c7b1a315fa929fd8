#!/usr/bin/env bash
# repl_session.sh - type lines into an interactive program inside a
# detached tmux session, as a person would, and print what the screen
# showed (whole scrollback, wrapped lines joined) on stdout.
#
#   tests/tools/repl_session.sh [options] LINES COMMAND [ARG...]
#   e.g. tests/tools/repl_session.sh lines.txt ./mvmpm repl scenarios/cylinder_bounce.lua
#
# LINES is a file ("-": stdin).  Each line is typed and followed by Enter,
# then the script waits until a fresh prompt shows (the cursor line, its
# trailing blanks removed, matches the prompt pattern, on a later screen
# line than where the typing began) or the per-line timeout passes.
# Lines starting with "@" are directives:
#   @key KEY...     send tmux key names (C-c, C-d, Up, Tab ...); no wait
#   @type TEXT      type TEXT without Enter; no wait
#   @nowait TEXT    type TEXT and Enter; no wait (start something long)
#   @wait           wait for a fresh prompt (after @nowait or @key C-c)
#   @sleep SECS     pause
#   @exit           wait until the program has ended
#   @# ...          comment
#   @@TEXT          type "@TEXT" (a line that starts with @)
#
# Options:
#   -t SECS   per-wait timeout (default 30)
#   -T SECS   timeout for the first prompt (default 60)
#   -p ERE    prompt pattern (default '^(mvmpm>|[[:space:]]*>>)$')
#   -x COLS   window width (default 200)
#   -y ROWS   window height (default 50)
#
# Exit status: 0 all went as expected; 1 a wait timed out or the program
# ended before its lines were all typed; 2 usage error.  Notes go to
# stderr.  A private tmux server (its own socket, no user config) is used
# and killed at the end, so nothing else running under tmux is touched.

set -u

timeout=30
startup=60
prompt='^(mvmpm>|[[:space:]]*>>)$'
cols=200
rows=50

usage() {
  sed -n '2,/^$/s/^# \{0,1\}//p' "$0" >&2
  exit 2
}

while getopts 't:T:p:x:y:h' opt; do
  case $opt in
    t) timeout=$OPTARG ;;
    T) startup=$OPTARG ;;
    p) prompt=$OPTARG ;;
    x) cols=$OPTARG ;;
    y) rows=$OPTARG ;;
    *) usage ;;
  esac
done
shift $((OPTIND - 1))
[ $# -ge 2 ] || usage
lines=$1
shift
if [ "$lines" = - ]; then
  exec 3<&0
elif [ -r "$lines" ]; then
  exec 3<"$lines"
else
  echo "repl_session: cannot read $lines" >&2
  exit 2
fi
command -v tmux >/dev/null || { echo "repl_session: tmux not found" >&2; exit 2; }

tmp=$(mktemp -d "${TMPDIR:-/tmp}/repl_session.XXXXXX") || exit 2
sock="repl_session_$$_$RANDOM"
T() { tmux -L "$sock" -f "$tmp/tmux.conf" "$@"; }
# shellcheck disable=SC2317  # run by the EXIT trap
cleanup() {
  T kill-server >/dev/null 2>&1
  rm -rf "$tmp"
}
trap cleanup EXIT
trap 'exit 1' INT TERM HUP

# The command runs through a script, so that no shell quoting is lost on
# the way through tmux, and which records its exit status (tmux's own
# record of it is racy); the pane stays after it ends, to be captured.
{
  echo '#!/usr/bin/env bash'
  # a trap, not an ignore: the program still gets Ctrl-C's default action,
  # but this shell survives it to record the status
  echo 'trap : INT QUIT'
  printf 'cd %q || exit 127\n' "$PWD"
  printf '%q ' "$@"
  printf '\necho "$?" >%q\n' "$tmp/status"
} >"$tmp/run"
chmod +x "$tmp/run"
cat >"$tmp/tmux.conf" <<EOF
set -g remain-on-exit on
set -g history-limit 1000000
set -g status off
set -g default-size ${cols}x${rows}
EOF

T new-session -d -s repl -x "$cols" -y "$rows" "$tmp/run" || exit 2

# absolute line of the cursor: scrollback lines plus row on screen
cursor() {
  local h y
  read -r h y < <(T display-message -p -t repl '#{history_size} #{cursor_y}')
  echo $((h + y))
}

dead() {
  [ "$(T display-message -p -t repl '#{pane_dead}' 2>/dev/null)" = 1 ]
}

# wait until the cursor sits on a bare prompt below line $1;
# 1 on timeout, 2 when the program has ended
waitprompt() {
  local mark=$1 limit=$2 start=$SECONDS y h text
  while :; do
    if dead; then
      return 2
    fi
    read -r h y < <(T display-message -p -t repl '#{history_size} #{cursor_y}')
    if [ $((h + y)) -gt "$mark" ]; then
      text=$(T capture-pane -p -t repl -S "$y" -E "$y")
      text=${text%"${text##*[![:space:]]}"}
      if [[ $text =~ $prompt ]]; then
        return 0
      fi
    fi
    if [ $((SECONDS - start)) -ge "$limit" ]; then
      return 1
    fi
    sleep 0.05
  done
}

# type text literally: a paste, since send-keys would take a trailing ';'
# as a tmux command separator
typetext() {
  [ -n "$1" ] || return 0
  printf '%s' "$1" | T load-buffer -b line - &&
    T paste-buffer -d -b line -t repl
}

status=0
note() { echo "repl_session: $*" >&2; }

# wait for the prompt after line $1, noting what went wrong
expect() {
  waitprompt "$mark" "$timeout"
  case $? in
    1) note "line $1: no prompt within ${timeout}s"; status=1 ;;
    2) note "line $1: program ended"; status=1 ;;
  esac
}

waitprompt -1 "$startup"
case $? in
  1) note "no prompt within ${startup}s"; status=1 ;;
  2) note "program ended before its first prompt"; status=1 ;;
esac

n=0
mark=$(cursor)
while [ $status = 0 ] && { IFS= read -r line <&3 || [ -n "$line" ]; }; do
  n=$((n + 1))
  if [ "$line" != @exit ] && dead; then
    note "program ended before line $n"
    status=1
    break
  fi
  case $line in
    @@*)
      line=${line#@}
      mark=$(cursor)
      typetext "$line"
      T send-keys -t repl Enter
      expect $n
      ;;
    '@#'*) ;;
    '@key '*)
      mark=$(cursor)
      # shellcheck disable=SC2086  # key names are separate words
      T send-keys -t repl ${line#@key }
      sleep 0.2
      ;;
    '@type '*)
      typetext "${line#@type }"
      ;;
    '@nowait '*)
      mark=$(cursor)
      typetext "${line#@nowait }"
      T send-keys -t repl Enter
      ;;
    @wait)
      expect $n
      ;;
    '@sleep '*)
      sleep "${line#@sleep }"
      ;;
    @exit)
      start=$SECONDS
      while ! dead && [ $((SECONDS - start)) -lt "$timeout" ]; do
        sleep 0.05
      done
      dead || { note "line $n: program still running after ${timeout}s"; status=1; }
      ;;
    @*)
      note "line $n: unknown directive: $line"
      status=2
      ;;
    *)
      mark=$(cursor)
      typetext "$line"
      T send-keys -t repl Enter
      expect $n
      ;;
  esac
done

# the whole scrollback, wrapped lines joined; tmux's closing "Pane is
# dead" line and the trailing blank lines dropped
T capture-pane -p -J -t repl -S - -E - | awk '
  { line[NR] = $0 }
  END {
    n = NR
    while (n > 0 && line[n] ~ /^[[:space:]]*$/) n--
    if (n > 0 && line[n] ~ /^Pane is dead \(/) n--
    while (n > 0 && line[n] ~ /^[[:space:]]*$/) n--
    for (i = 1; i <= n; i++) print line[i]
  }'
if dead; then
  note "program exited with status $(cat "$tmp/status" 2>/dev/null || echo unknown)"
fi
exit $status
