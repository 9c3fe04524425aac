#!/bin/sh
# One end-to-end case (called by CTest, see cases.cmake):
#   run_case.sh DELTRI VERIFY INPUT SWITCHES [options]
# SWITCHES is one argument such as -pc, or "none".
# INPUT is a file (copied into a fresh temp dir) or gen:NAME.EXT (written by gen_input below).
# deltri runs twice, in two fresh directories; the exit status must be the expected one, the output
# files of both runs byte-identical (determinism), and stderr identical.
# On success (exit 0) deltri_mesh_verify checks the mesh unless --no-verify.
# On failure (exit != 0) no output file may exist and stderr's first line must start with
# "INPUT:LINE:" (or the --error text).
# Options:
#   --exit N            expected exit status (default 0)
#   --warning TEXT      stderr must contain TEXT (may repeat)
#   --no-warning        stderr must be empty
#   --error TEXT        expected start of stderr's first line for a failing run
#   --verify ARGS       extra arguments for deltri_mesh_verify (e.g. "--expect-triangles 0")
#   --no-verify         do not run deltri_mesh_verify (e.g. with -N or -E)
#   --files "A B"       the output files that must exist (e.g. "x.1.ele x.1.poly"), and no others
#   --varies NAME       NAME (an output file, or "stderr") may differ between the two runs
#                       (timings in the JSON report or in the summary line)
#   --stdin             feed the input on standard input and name it "-" (outputs are stdin.1.*)
#   --stdout NAME       keep standard output as the file NAME in the run's directory (so it is
#                       compared between runs and counts as an output file)
#   --prior NAME        before the run, NAME holds a previous run's output; a failing run must
#                       leave it byte for byte as it was (may repeat)
#   --in-the-way NAME   before the run, a directory stands where the output NAME goes
#   --fsize BLOCKS      run deltri under `ulimit -f BLOCKS` with SIGXFSZ ignored: writes past the
#                       limit fail as on a full disk
#   --skip-as-root      exit 77 (CTest: skipped) when run as root, for permission cases
set -u
deltri=$1 verify=$2 input=$3 switches=$4
[ "$switches" = none ] && switches=
shift 4
expect_exit=0 error_text= verify_args= run_verify=1 files= no_warning=0 use_stdin=0 stdout_name= varies= priors= in_the_way= fsize=
warnings_file=$(mktemp) || exit 1
while [ $# -gt 0 ]; do
  case $1 in
    --exit) expect_exit=$2; shift ;;
    --warning) printf '%s\n' "$2" >>"$warnings_file"; shift ;;
    --no-warning) no_warning=1 ;;
    --error) error_text=$2; shift ;;
    --verify) verify_args=$2; shift ;;
    --no-verify) run_verify=0 ;;
    --files) files=$2; shift ;;
    --stdin) use_stdin=1 ;;
    --varies) varies="$varies $2"; shift ;;
    --stdout) stdout_name=$2; shift ;;
    --prior) priors="$priors $2"; shift ;;
    --in-the-way) in_the_way="$in_the_way $2"; shift ;;
    --fsize) fsize=$2; shift ;;
    --skip-as-root) [ "$(id -u)" = 0 ] && { echo "skipped: permissions do not bind root"; exit 77; } ;;
    *) echo "run_case.sh: unknown option $1" >&2; exit 2 ;;
  esac
  shift
done

work=$(mktemp -d) || exit 1
trap 'chmod -R u+w "$work"; rm -rf "$work" "$warnings_file"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }

# Generated inputs (POSIX sh + awk only).
star() {  # star CENTRE RADIUS: 40-gon with a 12-gon hole and 60 free vertices, radii jittered
  awk -v c="$1" -v s="$2" 'BEGIN { srand(11); pi = atan2(0, -1); print 112, 2, 0, 0
    for (k = 0; k < 40; k++) pt(0.85 + 0.15 * rand(), 2 * pi * (k + 0.3 * rand()) / 40)
    for (k = 0; k < 12; k++) pt(0.15 + 0.05 * rand(), 2 * pi * (k + 0.3 * rand()) / 12)
    for (k = 0; k < 60; k++) pt(0.3 + 0.5 * rand(), 2 * pi * rand())
    print 52, 0
    for (k = 0; k < 40; k++) print k + 1, k + 1, (k + 1) % 40 + 1
    for (k = 0; k < 12; k++) print 41 + k, 41 + k, 40 + (k + 1) % 12 + 1
    print 1; printf "1 %.17g %.17g\n", c, c }
  function pt(r, a) { printf "%d %.17g %.17g\n", ++n, c + s * r * cos(a), c + s * r * sin(a) }'
}
gen_input() {  # gen_input NAME.EXT DIR
  case $1 in
    gap_segments.poly)  # vertex indices 1, 2, 4 and a segment naming vertex 4
      printf '3 2 0 0\n1 0 0\n2 1 0\n4 0 1\n1 0\n1 1 4\n0\n' >"$2/$1" ;;
    grid30.node)  # 30 x 30 unit grid: every quad is cocircular
      awk 'BEGIN { print 900, 2, 0, 0; n = 1; for (i = 0; i < 30; i++) for (j = 0; j < 30; j++) print n++, i, j }' >"$2/$1" ;;
    offset.node)  # 400 pseudo-random points in [1e9, 1e9 + 1) on a 2^-10 lattice: 40 significant bits
      awk 'BEGIN { print 400, 2, 0, 0; s = 12345
        for (n = 1; n <= 400; n++) { s = (s * 16807) % 2147483647; x = s % 1024
          s = (s * 16807) % 2147483647; y = s % 1024
          printf "%d %.10f %.10f\n", n, 1000000000 + x / 1024, 1000000000 + y / 1024 } }' >"$2/$1" ;;
    collinear.node)  # 12 points on y = 2x + 1
      awk 'BEGIN { print 12, 2, 0, 0; for (i = 1; i <= 12; i++) print i, i * 0.5, 2 * i * 0.5 + 1 }' >"$2/$1" ;;
    star_1e9.poly) star 1000000000 100 >"$2/$1" ;;  # a star polygon and hole of radius 100 at (1e9, 1e9)
    star_1e-9.poly) star 0 1e-9 >"$2/$1" ;;          # the same of radius 1e-9 at the origin
    span.poly)  # a 2e6 square around a 2e-6 square hole, free vertices at 1e-3 and 1: sizes 1e-6 to 1e6
      printf '%s\n' '10 2 0 0' '1 -1e6 -1e6' '2 1e6 -1e6' '3 1e6 1e6' '4 -1e6 1e6' '5 -1e-6 -1e-6' '6 1e-6 -1e-6' \
        '7 1e-6 1e-6' '8 -1e-6 1e-6' '9 1e-3 0' '10 1 1' '8 0' '1 1 2' '2 2 3' '3 3 4' '4 4 1' '5 5 6' '6 6 7' \
        '7 7 8' '8 8 5' '1' '1 0 0' >"$2/$1" ;;
    garbage.node) printf '\177ELF\002\001\001\000\000\000\377\376\000\n\003\000>\000' >"$2/$1" ;;
    empty.node) : >"$2/$1" ;;
    dir.node) mkdir "$2/$1" ;;
    missing.*) ;;  # no file at all
    readonly_dir.node) printf '3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n' >"$2/$1"; chmod 555 "$2" ;;
    unreadable.node) printf '3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n' >"$2/$1"; chmod 000 "$2/$1" ;;
    crlf.node) printf '# Windows line ends\r\n3 2 0 0\r\n1 0 0\r\n2 1 0\r\n3 0 1\r\n' >"$2/$1" ;;
    crlf.poly) printf '4 2 0 1\r\n1 0 0 1\r\n2 1 0 1\r\n3 1 1 1\r\n4 0 1 1\r\n4 1\r\n1 1 2 5\r\n2 2 3 5\r\n3 3 4 5\r\n4 4 1 5\r\n0\r\n' >"$2/$1" ;;
    cr_only.node) printf '3 2 0 0\r1 0 0\r2 1 0\r3 0 1\r' >"$2/$1" ;;
    bom.node) printf '\357\273\277# UTF-8 byte order mark\n3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n' >"$2/$1" ;;
    nul.node) printf '3 2 0 0\n1 0 0\n2 1 \0000\n3 0 1\n' >"$2/$1" ;;
    no_newline.node) printf '3 2 0 0\n1 0 0\n2 1 0\n3 0 1' >"$2/$1" ;;
    annulus.poly)  # a 40-gon of radius 2 around a 20-gon hole of radius 1: every input angle above 60 degrees
      awk 'BEGIN { pi = atan2(0, -1); print 60, 2, 0, 1
        for (i = 0; i < 40; i++) printf "%d %.17g %.17g 1\n", i + 1, 2 * cos(2 * pi * i / 40), 2 * sin(2 * pi * i / 40)
        for (i = 0; i < 20; i++) printf "%d %.17g %.17g 2\n", i + 41, cos(2 * pi * i / 20), sin(2 * pi * i / 20)
        print 60, 1
        for (i = 0; i < 40; i++) printf "%d %d %d 1\n", i + 1, i + 1, (i + 1) % 40 + 1
        for (i = 0; i < 20; i++) printf "%d %d %d 2\n", i + 41, i + 41, (i + 1) % 20 + 41
        print 1; print 1, 0, 0 }' >"$2/$1" ;;
    ngon12.poly)  # a regular 12-gon of radius 1: every input angle 150 degrees
      awk 'BEGIN { pi = atan2(0, -1); print 12, 2, 0, 0
        for (i = 0; i < 12; i++) printf "%d %.17g %.17g\n", i + 1, cos(2 * pi * i / 12), sin(2 * pi * i / 12)
        print 12, 0
        for (i = 0; i < 12; i++) printf "%d %d %d\n", i + 1, i + 1, (i + 1) % 12 + 1
        print 0 }' >"$2/$1" ;;
    hexhole.poly)  # a 3 x 2 rectangle around a hexagonal hole: every input angle 90 or 240 degrees
      awk 'BEGIN { pi = atan2(0, -1); print 10, 2, 0, 1; printf "1 0 0 1\n2 3 0 1\n3 3 2 1\n4 0 2 1\n"
        for (i = 0; i < 6; i++) printf "%d %.17g %.17g 2\n", i + 5, 1.1 + 0.5 * cos(2 * pi * i / 6 + 0.3), 0.9 + 0.5 * sin(2 * pi * i / 6 + 0.3)
        print 10, 1
        for (i = 0; i < 4; i++) printf "%d %d %d 1\n", i + 1, i + 1, (i + 1) % 4 + 1
        for (i = 0; i < 6; i++) printf "%d %d %d 2\n", i + 5, i + 5, (i + 1) % 6 + 5
        print 1; print 1, 1.1, 0.9 }' >"$2/$1" ;;
    holes24.poly|holes3.poly)  # unit square with k x k holes, each a 40-gon (24: large enough to refine in halves)
      awk -v k="$(printf '%s' "$1" | tr -dc 0-9)" 'BEGIN { n = 40; pi = atan2(0, -1)
        printf "%d 2 0 1\n1 0 0 1\n2 1 0 1\n3 1 1 1\n4 0 1 1\n", 4 + k * k * n
        v = 4
        for (i = 0; i < k; i++) for (j = 0; j < k; j++) for (s = 0; s < n; s++)
          printf "%d %.17g %.17g 2\n", ++v, (i + 0.5) / k + 0.3 / k * cos(2 * pi * s / n), (j + 0.5) / k + 0.3 / k * sin(2 * pi * s / n)
        printf "%d 1\n1 1 2 1\n2 2 3 1\n3 3 4 1\n4 4 1 1\n", 4 + k * k * n
        e = 4
        for (h = 0; h < k * k; h++) for (s = 0; s < n; s++)
          printf "%d %d %d 2\n", ++e, 5 + h * n + s, 5 + h * n + (s + 1) % n
        printf "%d\n", k * k
        for (i = 0; i < k; i++) for (j = 0; j < k; j++) printf "%d %.17g %.17g\n", i * k + j + 1, (i + 0.5) / k, (j + 0.5) / k
      }' >"$2/$1" ;;
    *) echo "run_case.sh: unknown generated input $1" >&2; exit 2 ;;
  esac
}

run() {  # run DIR: copies the input into DIR and runs deltri there
  mkdir "$1"
  case $input in
    gen:*) name=${input#gen:}; gen_input "$name" "$1" ;;
    *) name=$(basename "$input"); cp "$input" "$1/$name" ;;
  esac
  out=../stdout.$2
  [ -n "$stdout_name" ] && out=$stdout_name
  for p in $priors; do printf 'output of a previous run\n' >"$1/$p"; done
  for d in $in_the_way; do mkdir "$1/$d"; done
  if [ -n "$fsize" ]; then
    # The limit binds deltri alone: its messages go through a pipe to a writer outside it.
    (cd "$1" && trap '' XFSZ && { (ulimit -f "$fsize" && exec "$deltri" $switches "$name" 2>&1 >"$out")
      echo $? >"$work/status.$2"; } | cat >../stderr.$2)
    return
  elif [ $use_stdin = 1 ]; then
    (cd "$1" && "$deltri" $switches - <"$name" >"$out" 2>../stderr.$2)
  else
    (cd "$1" && "$deltri" $switches "$name" >"$out" 2>../stderr.$2)
  fi
  echo $? >"$work/status.$2"
}

run "$work/a" 1
run "$work/b" 2
status=$(cat "$work/status.1")
echo "deltri $switches $name: exit $status"
sed 's/^/  stderr: /' "$work/stderr.1"
[ "$status" = "$expect_exit" ] || fail "exit status $status, expected $expect_exit"
[ "$(cat "$work/status.2")" = "$status" ] || fail "second run exit status differs"

# Determinism: the same files with the same bytes, the same messages.
(cd "$work/a" && ls) >"$work/list.a"
(cd "$work/b" && ls) >"$work/list.b"
cmp -s "$work/list.a" "$work/list.b" || fail "the two runs wrote different files"
for f in $(cat "$work/list.a"); do
  [ -f "$work/a/$f" ] || continue
  case " $varies " in *" $f "*) continue ;; esac
  cmp -s "$work/a/$f" "$work/b/$f" || fail "$f differs between two runs (not deterministic)"
done
case " $varies " in
  *" stderr "*) ;;
  *) cmp -s "$work/stderr.1" "$work/stderr.2" || fail "stderr differs between two runs" ;;
esac

# Warnings.
while IFS= read -r text; do
  grep -F -q -- "$text" "$work/stderr.1" || fail "stderr lacks the warning '$text'"
done <"$warnings_file"
if [ $no_warning = 1 ] && [ -s "$work/stderr.1" ]; then fail "unexpected messages on stderr"; fi

outputs=$(grep -v -x -F -- "$name" "$work/list.a")
if [ "$expect_exit" != 0 ] && [ -n "$stdout_name" ]; then
  [ -s "$work/a/$stdout_name" ] && fail "a failing run printed to standard output"
  outputs=$(printf '%s\n' "$outputs" | grep -v -x -F -- "$stdout_name")
fi
for p in $priors $in_the_way; do outputs=$(printf '%s\n' "$outputs" | grep -v -x -F -- "$p"); done
if [ "$expect_exit" != 0 ]; then
  [ -z "$outputs" ] || fail "a failing run left output files: $outputs"
  for p in $priors; do
    printf 'output of a previous run\n' | cmp -s - "$work/a/$p" || fail "the failing run changed the earlier output $p"
  done
  for d in $in_the_way; do [ -d "$work/a/$d" ] || fail "the failing run replaced the directory $d"; done
  first=$(head -n 1 "$work/stderr.1")
  if [ -n "$error_text" ]; then
    case $first in "$error_text"*) ;; *) fail "stderr's first line does not start with '$error_text'" ;; esac
  else
    shown=$name
    [ $use_stdin = 1 ] && shown="standard input"
    printf '%s\n' "$first" | grep -q "^$shown:[0-9][0-9]*: " || fail "stderr's first line is not '$shown:LINE: message'"
  fi
  exit $failed
fi

if [ -n "$files" ]; then
  expected=$(for f in $files; do echo "$f"; done | sort)
  [ "$(printf '%s\n' "$outputs" | sort)" = "$expected" ] || fail "output files are [$(echo $outputs)], expected [$files]"
fi

if [ $run_verify = 1 ]; then
  stem=${name%.*}
  [ $use_stdin = 1 ] && stem=stdin
  case $switches in *I*) base=$stem ;; *) base=$stem.1 ;; esac
  (cd "$work/a" && "$verify" --input "$name" --mesh "$base" $verify_args) || fail "deltri_mesh_verify found faults"
fi
exit $failed
