# Metamorphic cases: metamorphic.sh KIND INPUT SWITCHES (see the script for what each KIND checks).
set(MM_RUN ${CMAKE_CURRENT_SOURCE_DIR}/metamorphic/metamorphic.sh)
function(mm_case name kind input switches)
  add_test(NAME metamorphic.${name}
           COMMAND sh ${MM_RUN} $<TARGET_FILE:deltri> $<TARGET_FILE:deltri_mesh_verify> ${kind} ${input} ${switches})
  set_tests_properties(metamorphic.${name} PROPERTIES TIMEOUT 120)
endfunction()

set(D ${CMAKE_SOURCE_DIR}/data)
# Scaling by a power of two is exact for any input: real files with decimal coordinates too (up
# to the supported range of coordinates, +-2^200 and not all below 2^-150).
foreach(sw -p -pq30)
  foreach(k 10 -20 150 -140)
    mm_case(scale${k}.guitar${sw} scale:${k} ${D}/guitar.poly ${sw})
    mm_case(scale${k}.star${sw} scale:${k} gen:star.poly ${sw})
  endforeach()
  mm_case(scale7.water${sw} scale:7 ${D}/water.poly ${sw})
  mm_case(scale-5.touching-holes6${sw} scale:-5 ${D}/touching-holes6.poly ${sw})
  # Translation is exact only where the coordinates have bits to spare: lattice inputs.
  mm_case(translate20.star${sw} translate:20 gen:star.poly ${sw})
  mm_case(translate1.star5${sw} translate:1 gen:star5.poly ${sw})
endforeach()
foreach(sw none -q30)
  mm_case(scale-3.ukraine${sw} scale:-3 ${D}/ukraine.node ${sw})
  mm_case(scale4.robustness1${sw} scale:4 ${D}/robustness1.node ${sw})
endforeach()
# Integer coordinates from 15 to 333: +1024 is exact, but the refined vertices would round
# differently, so only the Delaunay triangulation is compared.
mm_case(translate10.ukraine translate:10 ${D}/ukraine.node none)
# Permuting the vertices of inputs in general position: the same triangles, mapped back.
foreach(seed 1 2 3)
  mm_case(permute${seed}.random-p permute:${seed} gen:random.poly -p)
endforeach()
mm_case(permute1.robustness1 permute:1 ${D}/robustness1.node none)
mm_case(permute2.playgrounds permute:2 ${D}/playgrounds-1356-epsg-3857.node none)
