# Regression inputs (fuzzer findings and the like): one CTest each, see regression/run.sh.
file(GLOB REGRESSION_INPUTS CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/regression/inputs/*)
foreach(input IN LISTS REGRESSION_INPUTS)
  get_filename_component(rname ${input} NAME)
  add_test(NAME regression.${rname}
           COMMAND sh ${CMAKE_CURRENT_SOURCE_DIR}/regression/run.sh $<TARGET_FILE:deltri> $<TARGET_FILE:deltri_mesh_verify> ${input})
  set_tests_properties(regression.${rname} PROPERTIES TIMEOUT 60)
endforeach()
