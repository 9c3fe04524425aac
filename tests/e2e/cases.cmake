# End-to-end CLI cases: one CTest per (input file, switch string).
# Each runs tests/e2e/run_case.sh: deltri twice in fresh temp dirs (outputs must be byte-identical),
# the exit status, expected warnings, and deltri_mesh_verify (tests/tools) on the mesh. Error cases
# check exit status, a "file:line:" message and that no output file was written.
set(E2E_RUN ${CMAKE_CURRENT_SOURCE_DIR}/e2e/run_case.sh)
set(E2E_DATA ${CMAKE_SOURCE_DIR}/data)
set(E2E_INPUTS ${CMAKE_CURRENT_SOURCE_DIR}/e2e/inputs)

# e2e_case(NAME INPUT SWITCHES [run_case.sh options...]); INPUT is a path or gen:NAME.EXT,
# SWITCHES one argument such as -pc, or "none".
function(e2e_case name input switches)
  add_test(NAME e2e.${name}
           COMMAND sh ${E2E_RUN} $<TARGET_FILE:deltri> $<TARGET_FILE:deltri_mesh_verify> ${input} ${switches} ${ARGN})
  set_tests_properties(e2e.${name} PROPERTIES TIMEOUT 120 SKIP_RETURN_CODE 77)
endfunction()

# ---- every sample in data/ ----
set(E2E_NODE_FILES issue44 playgrounds-1356-epsg-3857 robustness1 robustness2 robustness3 robustness4 ukraine)
set(E2E_POLY_FILES Constrained_Sweden corner_cases crossing-edges eberly-6 guitar issue-142-double-hanging-edge
    issue-42-hole-overlaps-bondary overlapping_constraints square_with_crack touching-holes6 water-huge water)
foreach(name IN LISTS E2E_NODE_FILES)
  e2e_case(${name}.default ${E2E_DATA}/${name}.node none)
  e2e_case(${name}.FC ${E2E_DATA}/${name}.node -FC)
  # -p name.node reads name.poly, as in Triangle (issue 46), so the point set's own case is -c.
  e2e_case(${name}.c ${E2E_DATA}/${name}.node -c)
endforeach()
foreach(name IN LISTS E2E_POLY_FILES)
  e2e_case(${name}.p ${E2E_DATA}/${name}.poly -p)
  e2e_case(${name}.pc ${E2E_DATA}/${name}.poly -pc --verify --convex-hull)
  e2e_case(${name}.pA ${E2E_DATA}/${name}.poly -pA)
  e2e_case(${name}.pO ${E2E_DATA}/${name}.poly -pO --verify --no-holes)
  e2e_case(${name}.pz ${E2E_DATA}/${name}.poly -pz)
  # -s: segments split at midpoints, which round off the line as refinement's split points do
  e2e_case(${name}.psC ${E2E_DATA}/${name}.poly -psC --verify --refined)
  e2e_case(${name}.pFC ${E2E_DATA}/${name}.poly -pFC)  # -F: Fortune's sweepline, checked
endforeach()
e2e_case(robustness2.warning ${E2E_DATA}/robustness2.node none --warning "32 duplicate vertices ignored")

# ---- output and algorithm switches on a .poly and a .node ----
set(G ${E2E_DATA}/guitar.poly)
e2e_case(guitar.pe ${G} -pe --files "guitar.1.node guitar.1.ele guitar.1.poly guitar.1.edge")
e2e_case(guitar.pn ${G} -pn --files "guitar.1.node guitar.1.ele guitar.1.poly guitar.1.neigh")
e2e_case(guitar.pen ${G} -pen --no-warning)
e2e_case(guitar.pI ${G} -pI --files "guitar.node guitar.ele")
e2e_case(guitar.pN ${G} -pN --no-verify --files "guitar.1.ele guitar.1.poly")
e2e_case(guitar.pE ${G} -pE --no-verify --files "guitar.1.node guitar.1.poly")
e2e_case(guitar.pB ${G} -pBen)
e2e_case(guitar.pP ${G} -pP --files "guitar.1.node guitar.1.ele")
e2e_case(guitar.pj ${G} -pj)
e2e_case(guitar.pV ${G} -pV)
e2e_case(guitar.pQ ${G} -pQ --no-warning)
e2e_case(guitar.pC ${G} -pC)
e2e_case(guitar.pi ${G} -pi)
e2e_case(guitar.pl ${G} -pl)
e2e_case(guitar.pF ${G} -pFC --no-warning)  # Fortune's sweepline, checked
e2e_case(guitar.pcjen ${G} -pcjen --verify --convex-hull)
set(U ${E2E_DATA}/ukraine.node)
e2e_case(ukraine.e ${U} -e --files "ukraine.1.node ukraine.1.ele ukraine.1.edge")
e2e_case(ukraine.n ${U} -n --files "ukraine.1.node ukraine.1.ele ukraine.1.neigh")
e2e_case(ukraine.I ${U} -I --files "ukraine.ele")
e2e_case(ukraine.N ${U} -N --no-verify --files "ukraine.1.ele")
e2e_case(ukraine.E ${U} -E --no-verify --files "ukraine.1.node")
e2e_case(ukraine.B ${U} -Ben)
e2e_case(ukraine.j ${U} -j)
e2e_case(ukraine.V ${U} -V)
e2e_case(ukraine.Q ${U} -Q)
e2e_case(ukraine.C ${U} -C)
e2e_case(ukraine.i ${U} -ien)
e2e_case(ukraine.l ${U} -len)
e2e_case(ukraine.F ${U} -FC --warning "7 duplicate vertices ignored")
e2e_case(water.pAen ${E2E_DATA}/water.poly -pAen)
e2e_case(water-huge.pcen ${E2E_DATA}/water-huge.poly -pcen --verify --convex-hull)
e2e_case(touching-holes6.pen ${E2E_DATA}/touching-holes6.poly -pen)

# ---- Triangle's other outputs: -v, -o2, -g (checked by deltri_mesh_verify: circumcentres,
# Voronoi edges and rays, midpoints, .off against .node/.ele), with -z, -I, -B, -j, -A, -c ----
e2e_case(guitar.pv ${G} -pv --files "guitar.1.node guitar.1.ele guitar.1.poly guitar.1.v.node guitar.1.v.edge")
e2e_case(guitar.po2 ${G} -po2)
e2e_case(guitar.pg ${G} -pg --files "guitar.1.node guitar.1.ele guitar.1.poly guitar.1.off")
e2e_case(guitar.pvgo2z ${G} -pvgo2ez)
# (-I next to the input .poly would have the verifier read the input as the output .poly.)
e2e_case(guitar.pvgo2I ${G} -pvgo2I --stdin --files "stdin.node stdin.ele stdin.v.node stdin.v.edge stdin.off")
e2e_case(guitar.pvgo2B ${G} -pvgo2Ben)
e2e_case(guitar.pvgo2j ${G} -pvgo2jA)
e2e_case(guitar.pcvgo2 ${G} -pcvgo2 --verify --convex-hull)
e2e_case(ukraine.vgo2 ${U} -vgo2 --files "ukraine.1.node ukraine.1.ele ukraine.1.v.node ukraine.1.v.edge ukraine.1.off")
e2e_case(ukraine.vgo2zIB ${U} -vgo2zIBN --files "ukraine.ele ukraine.v.node ukraine.v.edge ukraine.off" --no-verify)
e2e_case(water.pvgo2A ${E2E_DATA}/water.poly -pvgo2A)
e2e_case(grid30.vgo2 gen:grid30.node -vgo2 --verify "--expect-triangles 1682")
e2e_case(sq_attr.vo2 ${E2E_INPUTS}/sq_attr.node -vo2e)
e2e_case(collinear.vgo2 gen:collinear.node -vgo2 --warning "collinear" --verify "--expect-triangles 0")

# ---- pipes: input "-" from standard input, one output on standard output ----
e2e_case(stdin.poly ${G} -p --stdin --files "stdin.1.node stdin.1.ele stdin.1.poly")
e2e_case(stdin.node ${U} -vgo2 --stdin --files "stdin.1.node stdin.1.ele stdin.1.v.node stdin.1.v.edge stdin.1.off")
e2e_case(stdin.pzIvB ${G} -pzIvB --stdin --files "stdin.node stdin.ele stdin.v.node stdin.v.edge")
# (The summary line with its time goes to stderr there: -Q keeps the two runs' stderr equal.)
e2e_case(stdout.msh ${G} "-pq30Q --msh=-" --stdin --stdout out.msh --no-verify --no-warning --files out.msh)
e2e_case(stdout.vtu ${G} "-pzo2Q --vtu=-" --stdout out.vtu --no-verify --no-warning --files out.vtu)
e2e_case(stdout.svg ${U} "-Q --svg=-" --stdout out.svg --no-verify --files out.svg)
e2e_case(stdout.json.e ${G} "-peQ --json=-" --stdout out.json --varies out.json --no-verify --no-warning --files "out.json guitar.1.edge")
e2e_case(stdout.summary ${G} "-p --msh=-" --stdout out.msh --varies stderr --no-verify --warning "wrote standard output")
e2e_case(stdout.error ${E2E_INPUTS}/nonnumeric.node "--msh=-" --stdin --stdout out.msh --exit 1)
# A .poly piped in without -p: refused at its segment header (line 150 of guitar.poly), not meshed as a hull.
e2e_case(stdin.poly_without_p ${G} "-q30 --msh=-" --stdin --stdout out.msh --exit 1
         --error "standard input:150: this looks like a .poly (segment section)\; use -p")
e2e_case(long_files ${G} "-p --msh --vtu --svg --json" --varies guitar.1.json --files "guitar.1.node guitar.1.ele guitar.1.poly guitar.1.msh guitar.1.vtu guitar.1.svg guitar.1.json")
e2e_case(error.two_stdout ${G} "--msh=- --vtu=-" --exit 2 --error "deltri: -: only one")
e2e_case(error.long_option ${G} "--mesh" --exit 2 --error "deltri: --mesh: unknown option")

# ---- generated point sets ----
foreach(sw none -i -l -F)
  e2e_case(grid30${sw} gen:grid30.node ${sw} --verify "--expect-triangles 1682")
  e2e_case(offset1e9${sw} gen:offset.node ${sw} --no-warning)
  e2e_case(collinear${sw} gen:collinear.node ${sw} --warning "collinear" --verify "--expect-triangles 0")
endforeach()
e2e_case(two_points ${E2E_INPUTS}/two_points.node none --exit 1 --error "two_points.node: a triangulation needs at least 3 distinct vertices")
e2e_case(duplicates ${E2E_INPUTS}/duplicates.node none --warning "2 duplicate vertices")

# ---- PSLG repairs: valid mesh and the warning ----
e2e_case(repair.duplicate_endpoint ${E2E_INPUTS}/dup_vertex_segment.poly -pen --warning "moved from a duplicate vertex")
e2e_case(repair.zero_length ${E2E_INPUTS}/zero_length.poly -pen --warning "zero-length")
e2e_case(repair.repeated ${E2E_INPUTS}/repeated.poly -pen --warning "repeated segment")
e2e_case(repair.through_vertex ${E2E_INPUTS}/through_vertex.poly -pen --warning "pass exactly through vertices")
e2e_case(repair.overlap ${E2E_INPUTS}/overlap.poly -pen --warning "collinear overlap")
e2e_case(repair.crossing ${E2E_INPUTS}/crossing.poly -pen --warning "crossing")
e2e_case(repair.near_parallel ${E2E_INPUTS}/near_parallel.poly -pen --warning "crossing")

# ---- bad input: exit 1, "file:line:" message, no output ----
e2e_case(error.wrong_count ${E2E_INPUTS}/wrong_count.node none --exit 1)
e2e_case(accept.segment_range ${E2E_INPUTS}/segment_range.poly -pc --verify --convex-hull
         --warning "segment_range.poly:9: segment 2: second endpoint 9 is not a vertex (vertices are numbered 1 to 4): 1 segment naming no vertex dropped, as in Triangle")
e2e_case(error.non_numeric ${E2E_INPUTS}/nonnumeric.node none --exit 1)
e2e_case(error.nan ${E2E_INPUTS}/nan.node none --exit 1)
e2e_case(error.inf ${E2E_INPUTS}/inf.node none --exit 1)
e2e_case(error.missing_segments ${E2E_INPUTS}/missing_segments.poly -p --exit 1)
e2e_case(error.dimension3 ${E2E_INPUTS}/dim3.poly -p --exit 1)
e2e_case(error.binary gen:garbage.node none --exit 1)
e2e_case(error.empty gen:empty.node none --exit 1 --error "empty.node: ")
e2e_case(error.directory gen:dir.node none --exit 1 --error "dir.node: ")
# ---- bad switches: exit 2 (-k is a valid switch, so -t stands for an unknown letter) ----
e2e_case(error.switch ${G} -pt --exit 2 --error "deltri: -t: unknown switch")
# The exact text of --version, -a-1, a bare -a with nothing to apply, -h on -s, the JSON's version,
# Steiner counts and empty-mesh angle (tests/e2e/messages.sh).
add_test(NAME e2e.messages COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/e2e/messages.sh $<TARGET_FILE:deltri> ${E2E_DATA}
         ${E2E_INPUTS} ${PROJECT_VERSION})

# ---- -r: refine a previous mesh (round trip, refinement of a refined mesh, a bad .ele) ----
add_test(NAME e2e.refine_chain.guitar
         COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/e2e/refine_chain.sh $<TARGET_FILE:deltri> $<TARGET_FILE:deltri_mesh_verify> ${E2E_DATA}/guitar.poly)

# ---- small input angles: fans of spokes 1-5 degrees apart, a star of 2 degree spikes ----
# -q34 finishes meeting the bound; -q40 is beyond what refinement can reach, and the termination
# guard stops it with a report instead of running on (fan5 is small, so the cap comes quickly).
foreach(name fan120 star50 fan5)
  e2e_case(${name}.pq34 ${E2E_INPUTS}/${name}.poly -pq34 --no-warning --verify "--refined --min-angle 34")
endforeach()
e2e_case(fan5.pq40 ${E2E_INPUTS}/fan5.poly -pq40 --verify --refined --warning "the termination guard's cap"
         --warning "triangles miss the requested bounds")
# Above 34 degrees a run that cannot converge gives back the mesh that meets 34 degrees (no worse
# mesh for a higher bound: a cascade cut short had left triangles of 2 degrees away from the spokes).
e2e_case(fan120.pq40 ${E2E_INPUTS}/fan120.poly -pq40 --verify "--refined --min-angle 34"
         --warning "refinement cannot reach this angle bound here")
# star50 gave back its 34-degree mesh too until the second stage moved free vertices and served the
# worst triangles first (refinement.md, "-q40 and above"); now -q40 is met away from the spikes.
e2e_case(star50.pq40 ${E2E_INPUTS}/star50.poly -pq40 --no-warning --verify "--refined --min-angle 40")

# ---- thin domains: four vertices, and as many triangles as the length over the width asks for. The
# Steiner cap once counted input vertices (4,096 each) and stopped these at 16,384 points with angles
# of 15 and 0.5 degrees; it now follows the integral of 1/lfs^2 (termination_guard.h). ----
e2e_case(strip_3.3e-5.pq30 ${E2E_INPUTS}/strip_3.3e-5.poly -pq30 --no-warning --verify "--refined --min-angle 30")
e2e_case(strip_1e-5.pq33 ${E2E_INPUTS}/strip_1e-5.poly -pq33 --no-warning --verify "--refined --min-angle 33")
e2e_case(channel_bend.pq30 ${E2E_INPUTS}/channel_bend.poly -pq30 --no-warning --verify "--refined --min-angle 30")
# Guards, not measures: strip_1e-5 takes about 6 s of CPU in a quiet Release run (19 s of wall time
# at load 19 on 2 cores), several times that under check-sanitize, where 120 s can be hit.
set_tests_properties(e2e.strip_3.3e-5.pq30 e2e.strip_1e-5.pq33 e2e.channel_bend.pq30 PROPERTIES TIMEOUT 600)
# Size bounds no machine can meet are refused at once, with the estimate (exit 6, as out of memory).
e2e_case(error.area_too_small ${E2E_INPUTS}/plate.poly -pa1e-30 --exit 6 --error "deltri: the size bounds ask for about")

# ---- size bounds alone (no -q) keep skinny triangles, and every triangle must still meet the bound:
# the guard's feature floor once refused the split of a too-large triangle with a short edge (plate
# at -a0.01 and below, guitar at -a0.003). (guitar at -a0.0005, 313k triangles, where a free vertex
# a rounding error from a segment once blocked a split, now meets its bound too and passes
# meshcheck, but this verifier reports three boundary edges there as on no segment.) ----
foreach(area 0.01 0.003 0.001)
  e2e_case(plate.pa${area} ${E2E_INPUTS}/plate.poly -pa${area} --no-warning
           --verify "--refined --max-area ${area}")
endforeach()
e2e_case(guitar.pa0.003 ${E2E_DATA}/guitar.poly -pa0.003 --no-warning --verify "--refined --max-area 0.003")
set_tests_properties(e2e.guitar.pa0.003 PROPERTIES TIMEOUT 600)  # a guard: 3 s in a quiet Release run
# Refined in two parts (refine/refine_in_parts.h; -V says "refined in 2 parts apart, then seams of 376 edges" for -pq30):
# the seam must leave no trace, and both runs the same mesh whatever the threads' timing.
e2e_case(halves.holes24.pq30 gen:holes24.poly -pq30C --no-warning --verify "--refined --min-angle 30")
e2e_case(halves.holes24.pq33a gen:holes24.poly -pq33a0.0001C --no-warning --verify "--refined --min-angle 33 --max-area 0.0001")
# A generous guard, not a measure of speed: a quiet Release run takes about 4 s, and under
# check-sanitize on a busy machine the old 120 s was hit.
set_tests_properties(e2e.halves.holes24.pq30 e2e.halves.holes24.pq33a PROPERTIES TIMEOUT 600)
# robustness1's hull has vertices an ulp from its edges: a hull subsegment there cannot be split in
# doubles, and retrying it (after Chew's step had deleted free vertices) once went round to the
# Steiner cap. Locked after the first failure, the area-only run meets its bound at once.
add_test(NAME e2e.area_bound.robustness1.a0.93
         COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/e2e/area_bound.sh $<TARGET_FILE:deltri> ${E2E_DATA}/robustness1.node -a0.93 0.93)
# At the bottom of double precision (refine/bottom_scale.h, cdt/convex_hull.h): robustness1 and 3
# have vertices one or two ulps apart (at -q30 some of those pairs have no representable good
# triangle, and they fail), robustness4's grid points lie within an ulp of its hull edges, and
# near_hull.node has vertices 1e-11 inside a hull edge and others a fraction of an ulp inside.
# With the precision floor at 2^-36 of the coordinates all of these had kept 1e-13 degree angles.
set(QUALITY_BOUND sh ${CMAKE_CURRENT_SOURCE_DIR}/e2e/quality_bound.sh $<TARGET_FILE:deltri>)
# (Point sets, so -q: -p name.node would read name.poly, as in Triangle.)
add_test(NAME e2e.bottom_scale.robustness1.q20 COMMAND ${QUALITY_BOUND} ${E2E_DATA}/robustness1.node -q20 20)
add_test(NAME e2e.bottom_scale.robustness3.q20 COMMAND ${QUALITY_BOUND} ${E2E_DATA}/robustness3.node -q20 20)
foreach(q 30 33)
  add_test(NAME e2e.bottom_scale.robustness4.q${q} COMMAND ${QUALITY_BOUND} ${E2E_DATA}/robustness4.node -q${q} ${q})
endforeach()
add_test(NAME e2e.bottom_scale.robustness4.q30a0.0019
         COMMAND ${QUALITY_BOUND} ${E2E_DATA}/robustness4.node -q30a0.0019 30 0.0019)
foreach(q 20 30)
  add_test(NAME e2e.bottom_scale.near_hull.q${q} COMMAND ${QUALITY_BOUND} ${E2E_INPUTS}/near_hull.node -q${q} ${q})
endforeach()
# Stopped by -S, an area-only run reports its worst triangle by size, not by an angle it never asked for.
e2e_case(plate.pa0.001S10 ${E2E_INPUTS}/plate.poly -pa0.001S10 --verify --refined
         --warning "triangles miss the requested bounds (largest: " --warning "times its size bound near")

# ---- error discipline (docs/reliability.md has the table): one line, exit status, no output ----
set(I ${E2E_INPUTS})
foreach(name comments_only negative_count huge_count overflow_count one_vertex missing_y
        overflow_real hex marker_overflow negative_attributes huge_attributes dimension1)
  e2e_case(error.${name} ${I}/${name}.node none --exit 1)
endforeach()
foreach(name no_holes negative_holes short_holes short_regions real_endpoint nan_hole
        duplicate_section huge_segments inf_region)
  e2e_case(error.${name} ${I}/${name}.poly -p --exit 1)
endforeach()
e2e_case(error.zero_vertices_no_node ${I}/zero_vertices_no_node.poly -p --exit 1 --error "zero_vertices_no_node.node: No such file")
e2e_case(error.missing_file gen:missing.node none --exit 1 --error "missing.node: No such file")
e2e_case(error.unreadable gen:unreadable.node none --skip-as-root --exit 1 --error "unreadable.node: ")
e2e_case(error.cr_only gen:cr_only.node none --exit 1)
e2e_case(error.nul_byte gen:nul.node none --exit 1)
e2e_case(error.ele_input gen:missing.ele none --exit 1 --error "missing.node: ")
# Accepted as Triangle accepts them: DOS line ends, a UTF-8 byte order mark, no final newline,
# extra fields and trailing text.
e2e_case(accept.crlf_node gen:crlf.node none --verify "--expect-triangles 1")
e2e_case(accept.crlf_poly gen:crlf.poly -p --verify "--expect-triangles 2")
e2e_case(accept.bom gen:bom.node none --verify "--expect-triangles 1")
e2e_case(accept.no_final_newline gen:no_newline.node none --verify "--expect-triangles 1")
e2e_case(accept.trailing ${I}/trailing.node none --verify "--expect-triangles 1")
# Read as Triangle reads them, with a warning saying what was assumed (tests/e2e/triangle_compat.sh
# has the outputs): vertex indices out of sequence or not starting at 0 or 1 where nothing refers to
# them, a segment endpoint naming no vertex.
# (deltri_mesh_verify reads only regular numbering; triangle_compat.sh lenient checks the output.)
e2e_case(accept.index_gap ${I}/index_gap.node none --no-verify
         --warning "index_gap.node:5: vertex index 4 is out of sequence: expected 3 (1 vertex line out of sequence): vertices are numbered by their order in the file, as in Triangle")
e2e_case(accept.first_index5 ${I}/first_index5.node none --verify "--expect-triangles 1"
         --warning "first_index5.node:3: the first vertex is numbered 5, not 0 or 1: the output is numbered from 1 (0 with -z), as in Triangle")
e2e_case(accept.endpoint_zero ${I}/endpoint_zero.poly -pc --verify --convex-hull
         --warning "endpoint_zero.poly:9: segment 2: second endpoint 0 is not a vertex (vertices are numbered 1 to 4): 1 segment naming no vertex dropped")
# Where segments name the vertices by number, irregular indices are ambiguous: still an error.
e2e_case(error.index_gap_segments gen:gap_segments.poly -p --exit 1
         --error "gap_segments.poly:4: vertex index 4 is out of sequence: expected 3 (the segments name vertices by number")
# Bad switches: exit 2, "deltri: -X: ..." and nothing read or written.
e2e_case(error.switch_angle ${G} -pq60 --exit 2 --error "deltri: -q: ")
e2e_case(error.switch_area ${G} -pa0 --exit 1 --error "deltri: -a: ")  # Triangle refuses -a0 with 1 too
e2e_case(error.switch_negative ${G} -pq-5 --exit 2 --error "deltri: ")
e2e_case(error.refine_no_ele ${G} -pr --exit 1 --error "guitar.ele: ")
# Output failures: exit 4, "file: reason", no temporaries left, earlier outputs untouched.
e2e_case(output.full_disk ${G} -p --fsize 0 --exit 4 --error "guitar.1.node: " --prior guitar.1.node --prior guitar.1.ele)
# 2048 bytes: guitar.1.ele and guitar.1.poly fit, guitar.1.node does not.
e2e_case(output.full_disk_late ${G} -p --fsize 4 --exit 4 --error "guitar.1.node: File too large" --prior guitar.1.poly)
e2e_case(output.directory_in_the_way ${G} -p --in-the-way guitar.1.ele --prior guitar.1.node --exit 4 --error "guitar.1.ele: ")
e2e_case(output.unwritable_directory gen:readonly_dir.node none --skip-as-root --exit 4 --error "readonly_dir.1.")
# A failed run leaves a previous run's outputs as they were.
e2e_case(error.keeps_previous_output ${E2E_INPUTS}/nan.node none --exit 1 --prior nan.1.node --prior nan.1.ele)

# ---- extreme coordinates: far from the origin, tiny, and sizes from 1e-6 to 1e6 ----
foreach(name star_1e9 star_1e-9 span)
  e2e_case(extreme.${name}.p gen:${name}.poly -p)
  e2e_case(extreme.${name}.pq30 gen:${name}.poly -pq30 --verify "--refined --min-angle 30")
endforeach()
e2e_case(extreme.offset1e9.q30 gen:offset.node -q30 --no-verify)
# Beyond the supported range (+-2^200, and every vertex coordinate below 2^-150): a clean error.
# Refinement beyond +-2^200 and below 2^-150 runs scaled by a power of two (issue 47, item 11): the
# square at 1e77 is its two triangles, the triangle at 1e-90 its one (both already meet -q).
e2e_case(accept.coordinate_large ${I}/too_large.poly -pq --verify "--expect-triangles 2")
e2e_case(accept.coordinates_small ${I}/too_small.node -q --verify "--expect-triangles 1")
e2e_case(accept.marker_count2 ${I}/marker_count2.poly -pen --verify "--expect-triangles 2")

# ---- refinement against Triangle 1.6's counts and the quality bounds, on data/ ----
add_test(NAME e2e.refine.triangle_counts
         COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/e2e/triangle_counts.sh $<TARGET_FILE:deltri>
                 $<TARGET_FILE:deltri_mesh_verify> ${E2E_DATA} ${CMAKE_CURRENT_SOURCE_DIR}/e2e/triangle_counts.md)
# A guard, not a measure: 86 s in a Release build on 2 busy cores, several times that under the
# sanitizers.
set_tests_properties(e2e.refine.triangle_counts PROPERTIES TIMEOUT 1800)

# ---- -r with an .area file: every triangle meets the bound of the input triangle its centroid
# lies in (exact rational lookup in tests/e2e/area_inheritance.py), sparse and full files ----
foreach(input ${E2E_INPUTS}/plate.poly ${E2E_DATA}/guitar.poly ${E2E_DATA}/water.poly)
  get_filename_component(stem ${input} NAME_WE)
  set(modes sparse full)
  if(stem STREQUAL "water")
    set(modes sparse)  # full: 265k triangles, a minute of exact arithmetic in Python
  endif()
  foreach(mode IN LISTS modes)
    add_test(NAME e2e.area_inheritance.${stem}.${mode}
             COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/e2e/area_inheritance.py $<TARGET_FILE:deltri>
                     ${CMAKE_CURRENT_BINARY_DIR}/area_inheritance/${stem}.${mode} ${input} -pq30 ${mode})
    # A guard, not a measure: water.sparse takes 12 s of CPU (deltri's two runs and the check, whose
    # exact signs go to rationals only where a floating-point filter cannot decide).
    set_tests_properties(e2e.area_inheritance.${stem}.${mode} PROPERTIES TIMEOUT 600)
  endforeach()
endforeach()

# ---- small input angles force only the triangles inside them (issue 42): the unit square with 360
# spokes from its centre, one degree apart (tests/e2e/spokes.py draws it and checks every triangle
# outside the 1-degree angles against the bound with its own angles) ----
foreach(q 20 30)
  add_test(NAME e2e.spokes.pq${q}
           COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/e2e/spokes.py $<TARGET_FILE:deltri>
                   $<TARGET_FILE:deltri_mesh_verify> ${CMAKE_CURRENT_BINARY_DIR}/spokes.pq${q} ${q})
  set_tests_properties(e2e.spokes.pq${q} PROPERTIES TIMEOUT 300)
endforeach()

# ---- --strict: exit 3 when triangles miss the bounds for reasons other than a small input angle
# (at an input vertex or where input segments cross), and on an empty mesh; the mesh is still written ----
function(strict_case name input switches status warning json_check)
  add_test(NAME e2e.strict.${name}
           COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/e2e/strict.sh $<TARGET_FILE:deltri> ${input} ${switches} ${status} ${warning} ${json_check})
  set_tests_properties(e2e.strict.${name} PROPERTIES TIMEOUT 120)
endfunction()
# water.poly: segments that cross (19 crossings split) and overlap; triangles next to the crossings
# miss 30 degrees, forced by the angles the segments cross at (counted and said, --strict content).
strict_case(crossings ${E2E_DATA}/water.poly -pq30 0
            "deltri: warning: water.poly: 21 triangles miss the requested bounds next to crossings of input segments, forced by the angles the segments cross at"
            "0 < q['triangles_missing_bounds_at_input_crossings'] < q['missing_bounds_by_cause']['small_input_angle'] and q['triangles_missing_bounds_not_forced_by_input'] == 0")
# tiny_crossing.poly: two segments crossing at 0.014 degrees (the issue 18 report: a corpus outline
# whose segments cross at tiny angles gave exit 0 and 0 misses); every miss is next to that crossing,
# counted there and said.
strict_case(tiny_crossing ${E2E_INPUTS}/tiny_crossing.poly -pq30 0
            "deltri: warning: tiny_crossing.poly: 1 segment crossing split at a new vertex"
            "q['triangles_missing_bounds_at_input_crossings'] == q['missing_bounds_by_cause']['small_input_angle'] == q['triangles_missing_bounds'] > 0 and q['triangles_missing_bounds_not_forced_by_input'] == 0 and q['smallest_angle'] < 0.015")
# corner_cases.poly: no closed boundary, every triangle is outside the segments.
strict_case(empty ${E2E_DATA}/corner_cases.poly -pq30 3
            "deltri: warning: corner_cases.poly: every triangle lies outside the segments or in a hole: the mesh is empty (try -c or -O)"
            "m['triangles'] == 0")
# The same bound met where the only misses sit at small input angles (touching-holes6.poly), or nowhere (guitar.poly).
strict_case(small_input_angles ${E2E_DATA}/touching-holes6.poly -pq30 0
            "deltri: warning: touching-holes6.poly: 28 duplicate vertices ignored (kept the first of each)"
            "q['triangles_missing_bounds'] == q['missing_bounds_by_cause']['small_input_angle'] > 0")
# -S stops refinement: the misses the input does not explain are put down to the -S limit, and --strict refuses them.
strict_case(steiner_limit ${G} -pq30S10 3
            "deltri: warning: guitar.poly: refinement stopped at the -S limit of Steiner points"
            "q['missing_bounds_by_cause']['steiner_limits'] > 0 and q['missing_bounds_by_cause']['other'] == 0")
# The same with an area bound: the triangles left above it are size misses of the -S limit.
strict_case(steiner_limit_area ${G} -pa1S10 3
            "deltri: warning: guitar.poly: refinement stopped at the -S limit of Steiner points"
            "q['triangles_above_size_bound'] == q['missing_bounds_by_cause']['steiner_limits'] == q['triangles_missing_bounds'] > 0")

# Issue 16: thin domains (rectangles 1 x 1e-2 to 1 x 1e-5, an L-shaped channel) meet the angle
# bound with at most 1.1 times Triangle 1.6's triangle count (counts in thin_domains.md).
add_test(NAME e2e.refine.thin_domains
         COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/e2e/thin_domains.sh $<TARGET_FILE:deltri>
                 $<TARGET_FILE:deltri_mesh_verify> ${E2E_INPUTS} ${CMAKE_CURRENT_SOURCE_DIR}/e2e/thin_domains.md)
set_tests_properties(e2e.refine.thin_domains PROPERTIES TIMEOUT 600)

# ---- issue 23: Triangle's meaning where deltri differed (tests/e2e/triangle_compat.sh) ----
foreach(item refine_o2 z crossing_attributes lenient messages poly_output split_segments)
  add_test(NAME e2e.triangle_compat.${item}
           COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/e2e/triangle_compat.sh $<TARGET_FILE:deltri> ${E2E_INPUTS} ${item})
endforeach()

# ---- one triangulation, cocircular ties included (issue 23): divide and conquer, -l, -i and -F give
# the same triangles with the checker on, and those are the Delaunay triangulation of the
# symbolically perturbed points, judged with exact rationals in the script ----
add_test(NAME e2e.one_triangulation
         COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/e2e/one_triangulation.py $<TARGET_FILE:deltri>
                 ${CMAKE_CURRENT_BINARY_DIR}/one_triangulation)
set_tests_properties(e2e.one_triangulation PROPERTIES TIMEOUT 300)

# ---- the paper's modes on a hard input (issue 22) ----
# Sec. 7.2's second strategy on water.poly (29-degree corners, crossings): it used to split a boundary
# subsegment at a point outside it (two triangles over a nearly collinear segment: exit 5, triangles
# overlap) and to chase the 30 degrees on lattice triangles to the Steiner cap; then it ended with the
# count of triangles left under 30 degrees at the bottom of double precision. Since issue 16 the
# sure-fire rule (Sec. 6.2) stops the splits through the small angles earlier (18,636
# triangles; main made 489,561), and the run says the termination guard stopped refinement;
# deltri_mesh_verify is not run (its segment-chain check fails on the vertices an ulp apart near the
# small angles, as on Ruppert's plain -pq20 mesh of this file, before this change too).
e2e_case(water.ruppert_ib2 ${E2E_DATA}/water.poly "-pq20.7 --algorithm=ruppert --interior-bound=2" --no-verify
         --warning "where the termination guard stopped refinement")
set_tests_properties(e2e.water.ruppert_ib2 PROPERTIES TIMEOUT 900)
# --range-restricted past the paper's range (issue 42): at clusters' 6.8-degree angles the sure-fire rule refuses
# splits that the Terminator's shells would make, and a few triangles beside the angles stay under 30 degrees; the
# warning must say that the rule refused them, not leave the user to guess.
e2e_case(clusters.range_restricted ${CMAKE_SOURCE_DIR}/tests/refine/inputs/clusters.poly "-pq30 --range-restricted" --verify --refined
         --warning "refused by the sure-fire rule of Sec. 6.2")
# Large files are formatted in ranges by whichever writing thread is free (io/range_pool.h).
add_test(NAME e2e.writer_threads COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/e2e/writer_threads.sh $<TARGET_FILE:deltri>
         $<TARGET_FILE:deltri_bench_gen>)
set_tests_properties(e2e.writer_threads PROPERTIES TIMEOUT 300)

# -a alone makes no slivers (refine/terminator.cpp, kLeastCandidateLensDeg): at three area bounds
# each, deltri's smallest angle (computed by the test from the files) must be at least half of
# Triangle 1.6's on the same input and switches, the figure in the comment. The rotated squares
# have only right input angles; there Triangle's smallest is at most 13.03 degrees, and the test
# asks for 10. Before the candidates' lens, deltri left 0.0073 degrees on the 3-degree square.
foreach(deg 3 30 45)
  foreach(a 0.01 0.001 0.0001)
    add_test(NAME e2e.area_alone.rotated_square_${deg}.a${a}
             COMMAND ${QUALITY_BOUND} ${E2E_INPUTS}/rotated_square_${deg}.poly -pa${a} 10 ${a})
  endforeach()
endforeach()
# name, area, half of Triangle 1.6's smallest angle (Triangle's own figure after the #)
set(AREA_ALONE_CASES
    guitar 0.5376 2.136           # 4.2717
    guitar 0.05376 0.013          # 0.024919
    guitar 0.005376 0.00009       # 0.00018163
    box 0.09 0.106                # 0.2103
    box 0.0036 0.29               # 0.57882
    box 0.00036 0.024             # 0.047506
    overlapping_constraints 0.4368 3.194     # 6.3868
    overlapping_constraints 0.017472 0.492   # 0.98283
    overlapping_constraints 0.0017472 0.255  # 0.50917
    square_with_crack 0.01 0.285             # 0.56925
    square_with_crack 0.002 0.267            # 0.53403
    square_with_crack 0.0004 0.292           # 0.58377
    issue-42-hole-overlaps-bondary 0.06 0.529     # 1.0566
    issue-42-hole-overlaps-bondary 0.006 0.508    # 1.01757
    issue-42-hole-overlaps-bondary 0.00024 0.229)  # 0.45615
while(AREA_ALONE_CASES)
  list(POP_FRONT AREA_ALONE_CASES name a angle)
  add_test(NAME e2e.area_alone.${name}.a${a} COMMAND ${QUALITY_BOUND} ${E2E_DATA}/${name}.poly -pa${a} ${angle} ${a})
endwhile()

# ---- how outputs are put in place (issues 45 and 47): a signal between two renames, concurrent
# runs on other and on the same names, one directory under two names, refused output names ----
if(UNIX AND NOT APPLE)
  # Preloaded into deltri to reach the moment between two renames (tests/e2e/rename_hook.c); into
  # deltri_preloadable, the program's objects linked with the shared libc (deltri itself is static).
  add_library(deltri_rename_hook MODULE ${CMAKE_CURRENT_SOURCE_DIR}/e2e/rename_hook.c)
  target_link_libraries(deltri_rename_hook PRIVATE ${CMAKE_DL_LIBS})
  add_test(NAME e2e.outputs.rename_window
           COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/e2e/rename_window.sh $<TARGET_FILE:deltri_preloadable>
                   $<TARGET_FILE:deltri_rename_hook> ${E2E_DATA})
  set_tests_properties(e2e.outputs.rename_window PROPERTIES TIMEOUT 300 SKIP_RETURN_CODE 77)
endif()
add_test(NAME e2e.outputs.lock_aliases COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/e2e/lock_aliases.sh $<TARGET_FILE:deltri> ${E2E_DATA})
set_tests_properties(e2e.outputs.lock_aliases PROPERTIES TIMEOUT 1500 SKIP_RETURN_CODE 77)
if(UNIX AND NOT APPLE)
  add_test(NAME e2e.outputs.concurrent_names
           COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/e2e/concurrent_names.sh $<TARGET_FILE:deltri_preloadable>
                   $<TARGET_FILE:deltri_rename_hook> ${E2E_DATA})
  set_tests_properties(e2e.outputs.concurrent_names PROPERTIES TIMEOUT 900 SKIP_RETURN_CODE 77)
endif()
add_test(NAME e2e.outputs.names COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/e2e/output_names.sh $<TARGET_FILE:deltri> ${E2E_DATA})
set_tests_properties(e2e.outputs.names PROPERTIES TIMEOUT 300)
add_test(NAME e2e.outputs.each COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/e2e/each.sh $<TARGET_FILE:deltri>
                                   $<TARGET_FILE:deltri_mesh_verify> ${E2E_DATA})
set_tests_properties(e2e.outputs.each PROPERTIES TIMEOUT 300)

# ---- small input angles force only the triangles inside them (issue 42): guitar.poly at
# -q30a0.054 kept three triangles of 28.7-29.3 degrees across equal-shell edges beside 45-degree
# junctions, where Triangle 1.6 meets 30 ----
add_test(NAME e2e.shells.guitar.pq30a0.054 COMMAND ${QUALITY_BOUND} ${E2E_DATA}/guitar.poly -pq30a0.054 30 0.054)
e2e_case(shells.guitar.pq30a0.054.verify ${E2E_DATA}/guitar.poly -pq30a0.054 --no-warning --verify "--refined --min-angle 30 --max-area 0.054")

# ---- --smooth (docs/refinement.md, "Mesh improvement (--smooth)"): samples and generated polygons
# meshed without and with the pass; -C, deltri_mesh_verify with the bounds, --threads=1 and 2 the
# same files, the smallest angle not lower and the mean smallest angle higher. ----
add_test(NAME e2e.smooth
         COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/e2e/smooth.sh $<TARGET_FILE:deltri> $<TARGET_FILE:deltri_mesh_verify>
                 ${E2E_DATA} ${E2E_INPUTS})
set_tests_properties(e2e.smooth PROPERTIES TIMEOUT 300)

# ---- Triangle's command line where scripts notice (tests/e2e/triangle_cli.py) ----
foreach(item stock_u poly_for_node ignorable_letters dimension3 messages)
  add_test(NAME e2e.triangle_cli.${item}
           COMMAND /usr/bin/python3 ${CMAKE_CURRENT_SOURCE_DIR}/e2e/triangle_cli.py $<TARGET_FILE:deltri> ${E2E_INPUTS} ${E2E_DATA} ${item})
endforeach()

# ---- locally optimal Steiner points (docs/refinement.md, "Locally optimal Steiner points"):
# past the off-centres' ceiling (34-36 degrees on these, where they stop with a warning), every
# triangle meets the bound, checked by deltri_mesh_verify; the cascade guard is the same ----
e2e_case(ceiling.annulus.pq39 gen:annulus.poly -pq39 --no-warning --verify "--refined --min-angle 39")
e2e_case(ceiling.holes3.pq38 gen:holes3.poly -pq38 --no-warning --verify "--refined --min-angle 38")
e2e_case(ceiling.hexhole.pq38 gen:hexhole.poly "-pq38 --steiner=optimal" --no-warning --verify "--refined --min-angle 38")
e2e_case(ceiling.annulus.offcentre.pq39 gen:annulus.poly "-pq39 --steiner=offcentre" --verify "--refined --min-angle 34"
         --warning "refinement cannot reach this angle bound here")

# ---- -q40 and above (docs/refinement.md, "-q40 and above: moving free vertices, worst first"):
# the second stage of locally optimal points moves free vertices and serves the worst triangles
# first; before that every one of these stopped with the 34-degree mesh and a warning. The annulus
# is ring.poly's shape (a 40-gon around a 20-gon hole). Every triangle meets the bound by
# deltri_mesh_verify's check, and no warning ----
e2e_case(ceiling.q40.annulus gen:annulus.poly -pq40 --no-warning --verify "--refined --min-angle 40")
e2e_case(ceiling.q40.hexhole gen:hexhole.poly -pq40 --no-warning --verify "--refined --min-angle 40")
e2e_case(ceiling.q40.holes3 gen:holes3.poly -pq40 --no-warning --verify "--refined --min-angle 40")
e2e_case(ceiling.q40.ngon12 gen:ngon12.poly -pq40 --no-warning --verify "--refined --min-angle 40")
e2e_case(ceiling.q41.annulus gen:annulus.poly -pq41 --no-warning --verify "--refined --min-angle 41")
