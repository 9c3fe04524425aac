# Regression inputs (fuzzer findings and the like): one CTest each, see regression/run.sh.
file(GLOB REGRESSION_INPUTS CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/regression/inputs/*)
foreach(input IN LISTS REGRESSION_INPUTS)
  get_filename_component(rname ${input} NAME)
  add_test(NAME regression.${rname}
           COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/regression/run.sh $<TARGET_FILE:deltri> $<TARGET_FILE:deltri_mesh_verify> ${input})
  set_tests_properties(regression.${rname} PROPERTIES TIMEOUT 60)
endforeach()

# Reproducers of bugs found but not fixed yet (see docs/reliability.md, "Open findings"): registered
# but disabled, so that CTest lists them as "Not Run (Disabled)" until the fix lands; then the file
# moves to inputs/.
file(GLOB OPEN_REGRESSION_INPUTS CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/regression/open/*)
foreach(input IN LISTS OPEN_REGRESSION_INPUTS)
  get_filename_component(rname ${input} NAME)
  add_test(NAME regression.open.${rname}
           COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/regression/run.sh $<TARGET_FILE:deltri> $<TARGET_FILE:deltri_mesh_verify> ${input})
  set_tests_properties(regression.open.${rname} PROPERTIES TIMEOUT 60 DISABLED TRUE)
endforeach()
