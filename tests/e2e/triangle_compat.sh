#!/bin/sh
# Issue 23: where deltri follows Triangle 1.6, one check per item against the behaviour the issue
# describes (Triangle itself is not run):
#   triangle_compat.sh DELTRI INPUTS_DIR ITEM      ITEM: refine_o2 | z | crossing_attributes |
#                                                        lenient | messages | poly_output
set -u
deltri=$1 inputs=$2 item=$3
work=$(mktemp -d) || exit 1
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failed=0
fail() { echo "FAIL: $*"; failed=1; }
# The first data line of a file (its header), and data line N+1 (its Nth record).
header() { awk '!/^[[:space:]]*(#|$)/ { print; exit }' "$1"; }
record() { awk -v n="$2" '!/^[[:space:]]*(#|$)/ { if (k++ == n) { print; exit } }' "$1"; }
count() { header "$1" | awk '{ print $1 }'; }

case $item in
refine_o2)
  # 1. -r of a six-node mesh: the midpoints of the input are dropped (Triangle: 8 vertices, not 25,
  # for 8 points). No vertex of the .node may be unused or lie on another one.
  printf '8 2 0 0\n1 0 0\n2 1 0\n3 2 0\n4 0 1\n5 1 1.2\n6 2 1\n7 0.5 2\n8 1.5 2.1\n' >pts.node
  "$deltri" -Q -o2 pts.node || fail "-o2 failed"
  [ "$(header pts.1.ele | awk '{ print $2 }')" = 6 ] || fail "-o2 wrote no six-node .ele"
  [ "$(count pts.1.node)" -gt 8 ] || fail "-o2 added no midpoints"
  "$deltri" -Q -r pts.1 || fail "-r of the -o2 mesh failed"
  [ "$(count pts.2.node)" = 8 ] || fail "-r pts.1: $(count pts.2.node) vertices, Triangle has 8"
  for sw in -rq -rqo2 -rqa0.05o2; do
    rm -f pts.2.*
    "$deltri" -Q $sw pts.1 || fail "$sw failed"
    # Every vertex is used (a corner, or a midpoint with -o2) and no two share a point.
    awk -v sw="$sw" 'FNR == 1 && !/^#/ { f++ }
      /^[[:space:]]*(#|$)/ { next }
      f == 1 && FNR > 1 { if (($2, $3) in at) { print "FAIL: " sw ": vertices " at[$2, $3] " and " $1 " coincide"; bad = 1 }; at[$2, $3] = $1; n++ }
      f == 2 && FNR > 1 { for (i = 2; i <= NF && i <= 7; i++) used[$i] = 1 }
      END { for (k in at) if (!(at[k] in used)) { print "FAIL: " sw ": vertex " at[k] " is used by no triangle"; bad = 1 }
            exit bad }' pts.2.node pts.2.ele || failed=1
    echo "$sw pts.1: $(count pts.2.node) vertices, $(count pts.2.ele) triangles"
  done ;;
z)
  # 2. The input's first index decides; -z numbers only an input whose first index is neither 0
  # nor 1 (Triangle: `-pzAen plate.poly` gives "1 0 0 5" as the first vertex).
  cp "$inputs/plate.poly" . && cp "$inputs/first_index5.node" .
  "$deltri" -Q -pzAen plate.poly || fail "-pzAen failed"
  [ "$(record plate.1.node 1)" = "1 0 0 5" ] || fail "-pzAen plate.poly: first vertex '$(record plate.1.node 1)', Triangle '1 0 0 5'"
  for f in ele edge neigh poly; do
    [ "$f" = poly ] && n=2 || n=1
    first=$(record plate.1.$f $n | awk '{ print $1 }')
    [ "$first" = 1 ] || fail "-pzAen: plate.1.$f numbered from $first"
  done
  awk 'NR > 1 && !/^#/ && $1 == 0' plate.1.ele | grep -q . && fail "-pzAen: a triangle names vertex 0"
  # A 0-based input stays 0-based with and without -z.
  printf '4 2 0 1\n0 0 0 5\n1 1 0 5\n2 1 1 5\n3 0 1 5\n4 1\n0 0 1 5\n1 1 2 5\n2 2 3 5\n3 3 0 5\n0\n' >zero.poly
  for sw in -pQ -pzQ; do
    rm -f zero.1.*
    "$deltri" $sw zero.poly || fail "$sw zero.poly failed"
    [ "$(record zero.1.node 1)" = "0 0 0 5" ] || fail "$sw zero.poly: first vertex '$(record zero.1.node 1)'"
  done
  # First index 5 (nothing refers to the numbers): numbered from 1, or from 0 with -z.
  "$deltri" -Q first_index5.node 2>/dev/null || fail "first_index5.node failed"
  [ "$(record first_index5.1.node 1 | awk '{ print $1 }')" = 1 ] || fail "first_index5.node: not numbered from 1"
  "$deltri" -Qz first_index5.node 2>/dev/null || fail "-z first_index5.node failed"
  [ "$(record first_index5.1.node 1 | awk '{ print $1 }')" = 0 ] || fail "-z first_index5.node: not numbered from 0" ;;
crossing_attributes)
  # 5. A crossing vertex gets the attributes interpolated along the segment it splits (the earlier
  # one): the diagonal 1-3 runs from 0 to 100, so its midpoint is 50; along 2-4 it would be 60.
  printf '4 2 1 0\n1 0 0 0\n2 10 0 40\n3 10 10 100\n4 0 10 80\n6 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 1 3\n6 2 4\n0\n' >x.poly
  "$deltri" -Q -p x.poly 2>/dev/null || fail "-p x.poly failed"
  [ "$(record x.1.node 5)" = "5 5 5 50 0" ] || fail "crossing vertex: '$(record x.1.node 5)', expected '5 5 5 50 0'"
  # A quarter of the way along: the diagonal 1-3 is crossed at (2.5, 2.5) by 2-5 with 5 at (-5,5).
  printf '5 2 1 0\n1 0 0 0\n2 10 0 40\n3 10 10 100\n4 0 10 80\n5 -5 5 7\n2 0\n1 1 3\n2 2 5\n0\n' >y.poly
  "$deltri" -Q -p y.poly 2>/dev/null || fail "-p y.poly failed"
  [ "$(record y.1.node 6 | awk '{ print $2, $3, $4 }')" = "2.5 2.5 25" ] || fail "crossing vertex: '$(record y.1.node 6)', expected 2.5 2.5 25" ;;
lenient)
  # 6. Read what Triangle reads where the meaning is plain, with a warning; an error where not.
  printf '4 2 1 1\n1 0 0 3 1\n2 1 0 4\n3 1 1 5 1\n4 0 1 6\n3 1\n1 1 2 7\n2 2 3\n3 3 9 1\n0\n' >loose.poly
  "$deltri" -Q -pc loose.poly 2>err || fail "loose.poly: exit $?"
  grep -q -x "deltri: warning: loose.poly:3: 2 vertices have no boundary marker: 0 assumed, as in Triangle" err || fail "marker warning: $(cat err)"
  grep -q -x "deltri: warning: loose.poly:8: 1 segment has no boundary marker: 0 assumed, as in Triangle" err || fail "segment marker warning: $(cat err)"
  grep -q "^deltri: warning: loose.poly:9: segment 3: second endpoint 9 is not a vertex (vertices are numbered 1 to 4): 1 segment naming no vertex dropped, as in Triangle$" err ||
    fail "endpoint warning: $(cat err)"
  [ "$(count loose.1.node)" = 4 ] || fail "loose.poly: $(count loose.1.node) vertices"
  [ "$(record loose.1.node 2 | awk '{ print $4 }')" = 4 ] || fail "vertex 2's attribute: $(record loose.1.node 2)"
  # Vertex 2 had no marker: 0, then the marker of its segment 1-2 (Triangle's rule for unmarked vertices).
  [ "$(record loose.1.node 2 | awk '{ print $5 }')" = 7 ] || fail "vertex 2's marker: $(record loose.1.node 2)"
  [ "$(count loose.1.poly)" = 0 ] || fail "loose.1.poly lists vertices"
  # Gaps where the segments name vertices by number: ambiguous, an error, no output.
  printf '4 2 0 0\n1 0 0\n2 1 0\n5 1 1\n6 0 1\n1 0\n1 1 5\n0\n' >gap.poly
  "$deltri" -Q -p gap.poly 2>err
  [ $? = 1 ] || fail "gap.poly with segments: exit status not 1"
  grep -q "^gap.poly:4: vertex index 5 is out of sequence: expected 3 (the segments name vertices by number" err || fail "gap.poly: $(cat err)"
  ls gap.1.* >/dev/null 2>&1 && fail "gap.poly: output written"
  # The same gaps without segments: read, numbered by position.
  printf '4 2 0 0\n1 0 0\n2 1 0\n5 1 1\n6 0 1\n' >gap.node
  "$deltri" -Q gap.node 2>err || fail "gap.node failed"
  grep -q "^deltri: warning: gap.node:4: vertex index 5 is out of sequence: expected 3 (2 vertex lines out of sequence)" err || fail "gap.node: $(cat err)"
  [ "$(record gap.1.node 4 | awk '{ print $1, $2, $3 }')" = "4 0 1" ] || fail "gap.node: vertex 4 is '$(record gap.1.node 4)'"
  # -r with a gap in the .node: the .ele names vertices by number.
  "$deltri" -Q -r gap.1 >/dev/null 2>&1 || fail "-r gap.1 failed"
  printf '3 2 0 0\n1 0 0\n2 1 0\n4 0 1\n' >g2.node && printf '1 3 0\n1 1 2 3\n' >g2.ele
  "$deltri" -Q -r g2 2>err
  [ $? = 1 ] || fail "-r with a gap: exit status not 1"
  grep -q "^g2.node:4: vertex index 4 is out of sequence: expected 3 (the triangles of g2.ele name vertices by number" err || fail "-r g2: $(cat err)"
  # "010" is ten (decimal), not Triangle's octal eight.
  awk 'BEGIN { print 10, 2, 0, 0; for (i = 1; i <= 10; i++) print i, i % 4, int(i / 4) + (i % 3) / 7; print 1, 0; print 1, 1, "010"; print 0 }' >ten.poly
  "$deltri" -Q -pc ten.poly || fail "ten.poly failed"
  awk 'NR > 1 && !/^#/ && NF >= 3 && (($2 == 1 && $3 == 10) || ($2 == 10 && $3 == 1))' ten.1.poly | grep -q . ||
    fail "ten.poly: no segment 1-10 in the output .poly" ;;
messages)
  # 7. Triangle's labelled counts with --triangle-messages; -pa0 exits 1 as in Triangle; bare -u runs.
  cp "$inputs/plate.poly" .
  "$deltri" -p --triangle-messages plate.poly >out || fail "--triangle-messages failed"
  for line in "  Input vertices: 10" "  Input segments: 11" "  Input holes: 1" "  Mesh vertices: 10" "  Mesh triangles: 10" \
      "  Mesh edges: 20" "  Mesh exterior boundary edges: 10" "  Mesh interior boundary edges: 1" "  Mesh subsegments (constrained edges): 11"; do
    grep -q -x -- "$line" out || fail "--triangle-messages: no line '$line'"
  done
  t=$(count plate.1.ele)
  grep -q -x "  Mesh triangles: $t" out || fail "Mesh triangles differs from the .ele's $t"
  "$deltri" -pV --triangle-messages plate.poly >out || fail "-V --triangle-messages failed"
  grep -q "^  Smallest angle: .*|  Largest angle: " out || fail "-V: no Smallest angle line"
  grep -q "^  Smallest area: .*0.25 .*|  Largest area: .*1.5$" out || fail "-V: areas: $(grep area out)"
  "$deltri" -pa0 plate.poly >out 2>err
  [ $? = 1 ] || fail "-pa0: exit status not 1 (Triangle's)"
  # Bare -u runs Triangle's stock size test (issue 46; e2e.triangle_cli.stock_u checks the mesh).
  "$deltri" -pu plate.poly >out 2>err || fail "bare -u: exit status $? ($(cat err))"
  "$deltri" -rI plate >out 2>err
  [ $? = 1 ] || fail "-rI: exit status not 1 (Triangle's)" ;;
poly_output)
  # 8. The output .poly: regions only with -A or a bare -a, holes kept with -O; -j's count.
  cp "$inputs/plate.poly" .
  # section headers: node header, segment header (+ segments), hole header (+ holes), region header
  sections() {  # prints: segments holes regions(or -)
    awk '/^[[:space:]]*(#|$)/ { next } { line[++n] = $0 }
      END { split(line[1], h); i = 2 + h[1]; split(line[i], s); i += s[1] + 1; split(line[i], o); i += o[1] + 1
            r = (i <= n) ? line[i] : "-"; split(r, rr); print s[1], o[1], rr[1] }' "$1"
  }
  "$deltri" -Q -p plate.poly || fail "-p failed"
  set -- $(sections plate.1.poly)
  [ "$2 $3" = "1 -" ] || fail "-p: holes/regions '$2 $3', expected '1 -' (no region section)"
  "$deltri" -Q -pA plate.poly || fail "-pA failed"
  set -- $(sections plate.1.poly)
  [ "$3" = 2 ] || fail "-pA: region section '$3', expected 2 regions"
  "$deltri" -Q -pa plate.poly || fail "-pa failed"
  set -- $(sections plate.1.poly)
  [ "$3" = 2 ] || fail "-pa: region section '$3', expected 2 regions"
  "$deltri" -Q -pO plate.poly || fail "-pO failed"
  set -- $(sections plate.1.poly)
  [ "$2" = 1 ] || fail "-pO: $2 holes in the output .poly, expected 1"
  [ "$(count plate.1.ele)" = 12 ] || fail "-pO: $(count plate.1.ele) triangles, expected the window meshed too (12)"
  # -j with -o2: the summary's vertex count is the .node's.
  for f in plate; do
    "$deltri" -pjo2 $f.poly >out || fail "-pjo2 failed"
    said=$(sed 's/.*-> \([0-9]*\) vertices.*/\1/' out)
    [ "$said" = "$(count $f.1.node)" ] || fail "-pjo2: summary says $said vertices, the .node has $(count $f.1.node)"
  done
  # A square with a square hole and a vertex inside the hole, which -j leaves out.
  printf '9 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n5 1 1\n6 3 1\n7 3 3\n8 1 3\n9 2 2.5\n8 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 5 6\n6 6 7\n7 7 8\n8 8 5\n1\n1 1.5 1.5\n' >hole_vertex.poly
  "$deltri" -pjo2 hole_vertex.poly >out || fail "-pjo2 hole_vertex failed"
  said=$(sed 's/.*-> \([0-9]*\) vertices.*/\1/' out)
  [ "$(count hole_vertex.1.node)" = 24 ] || fail "-pjo2 hole_vertex: $(count hole_vertex.1.node) vertices written, expected 8 + 16 midpoints"
  [ "$said" = "$(count hole_vertex.1.node)" ] || fail "-pjo2: summary says $said vertices, the .node has $(count hole_vertex.1.node)" ;;
split_segments)
  # 3. -s: a segment missing from the Delaunay triangulation is split at its midpoint, recursively,
  # until its pieces are edges (guitar.poly: Triangle has 148 vertices in 152 triangles, -p 144 in 148).
  cp "$inputs/../../../data/guitar.poly" . || fail "no data/guitar.poly"
  "$deltri" -Q -ps guitar.poly || fail "-ps guitar.poly failed"
  [ "$(count guitar.1.ele)" = 152 ] || fail "-ps guitar.poly: $(count guitar.1.ele) triangles, Triangle 152"
  used=$(awk 'FNR == 1 || /^[[:space:]]*(#|$)/ { next } { u[$2]; u[$3]; u[$4] } END { print length(u) }' guitar.1.ele)
  [ "$used" = 148 ] || fail "-ps guitar.poly: $used vertices in triangles, Triangle 148"
  # A diagonal through a square of points that the Delaunay triangulation crosses: every new vertex
  # is a dyadic point of the diagonal (x = y = 8k/2^j) and the diagonal's pieces are edges.
  awk 'BEGIN { print 12, 2, 0, 0; n = 0
    print ++n, 0, 0; print ++n, 8, 0; print ++n, 8, 8; print ++n, 0, 8
    for (i = 0; i < 8; i++) print ++n, 1 + i * 0.8, 1 + i * 0.8 + ((i % 2) ? 0.3 : -0.3)
    print 5, 0; print 1, 1, 2; print 2, 2, 3; print 3, 3, 4; print 4, 4, 1; print 5, 1, 3; print 0 }' >diag.poly
  "$deltri" -Q -psC diag.poly || fail "-psC diag.poly failed"
  new=$(($(count diag.1.node) - 12))
  [ $new -gt 0 ] || fail "-ps diag.poly: no midpoint inserted"
  awk 'FNR == 1 || /^[[:space:]]*(#|$)/ { next } $1 > 12 {
         if ($2 != $3) { print "FAIL: vertex " $1 " (" $2 ", " $3 ") is off the diagonal"; bad = 1 }
         t = $2 / 8; for (k = 0; k < 60 && t != int(t); k++) t *= 2
         if (t != int(t)) { print "FAIL: vertex " $1 " is not a dyadic point of the diagonal"; bad = 1 } } END { exit bad }' diag.1.node || failed=1
  # The diagonal's pieces are all in the output .poly: their lengths add up to the diagonal's.
  awk 'FNR == 1 { f++ } /^[[:space:]]*(#|$)/ { next }
       f == 1 && FNR > 1 { x[$1] = $2; y[$1] = $3 }
       f == 2 && FNR > 2 && NF >= 3 && x[$2] == y[$2] && x[$3] == y[$3] { s += sqrt((x[$2] - x[$3]) ^ 2 + (y[$2] - y[$3]) ^ 2); n++ }
       END { if (n < 2 || (s - 8 * sqrt(2)) ^ 2 > 1e-20) { print "FAIL: diagonal pieces " n ", length " s; exit 1 } }' diag.1.node diag.1.poly || failed=1
  echo "-ps diag.poly: $new midpoints" ;;
*)
  echo "triangle_compat.sh: unknown item $item" >&2
  exit 2 ;;
esac
[ $failed = 0 ] && echo "$item: as described in issue 23"
exit $failed
