# The library (issue 21): the C library installed and used by a C client and a CMake consumer,
# the C++ API from 8 threads at once, bad input through the API, the Python module and the size
# field. See docs/library.md.
set(API_DIR ${CMAKE_CURRENT_SOURCE_DIR}/api)
if(DELTRI_SANITIZE)
  set(API_SANITIZE_FLAGS "-fsanitize=address,undefined")
else()
  set(API_SANITIZE_FLAGS "")
endif()
add_test(NAME api.c_client COMMAND sh ${API_DIR}/c_client_test.sh ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR} "${API_SANITIZE_FLAGS}")
set_tests_properties(api.c_client PROPERTIES TIMEOUT 600)
