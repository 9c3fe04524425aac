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
set_tests_properties(api.c_client PROPERTIES TIMEOUT 600 SKIP_RETURN_CODE 77)
add_test(NAME api.cmake_consumer COMMAND sh ${API_DIR}/consumer_test.sh ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR} "${API_SANITIZE_FLAGS}")
set_tests_properties(api.cmake_consumer PROPERTIES TIMEOUT 600)
add_executable(test_api_threads ${API_DIR}/test_threads.cpp)
target_compile_options(test_api_threads PRIVATE ${DELTRI_WARNINGS})
target_link_libraries(test_api_threads PRIVATE deltri_core)
add_test(NAME api.threads COMMAND test_api_threads ${CMAKE_SOURCE_DIR}/data)
set_tests_properties(api.threads PROPERTIES TIMEOUT 600)
add_executable(test_api_bad_input ${API_DIR}/test_bad_input.c)
target_link_libraries(test_api_bad_input PRIVATE deltri_shared)
target_include_directories(test_api_bad_input PRIVATE ${CMAKE_SOURCE_DIR}/src/api)
add_test(NAME api.bad_input COMMAND test_api_bad_input)
# The Python module: Debian's python3 with numpy (installed by make test's set-up), on this build's
# libdeltri. Skipped (77) without numpy, saying what installs it.
# Under the sanitizers the library needs their runtimes loaded first, which python is not built
# with: they are preloaded, and python's own leaks at exit are not reported (api.bad_input checks
# the library's under LeakSanitizer).
set(API_NEEDS_NUMPY "/usr/bin/python3 -c 'import numpy' 2>/dev/null || { echo 'SKIP: missing python3-numpy; install with: sudo apt-get install -y python3-numpy'; exit 77; }; exec /usr/bin/python3 \"$@\"")
set(API_PYTHON_ENV "DELTRI_LIBRARY=$<TARGET_FILE:deltri_shared>" "PYTHONPATH=${CMAKE_SOURCE_DIR}/src/api/python")
if(DELTRI_SANITIZE)
  execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=libasan.so OUTPUT_VARIABLE API_ASAN OUTPUT_STRIP_TRAILING_WHITESPACE)
  execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=libubsan.so OUTPUT_VARIABLE API_UBSAN OUTPUT_STRIP_TRAILING_WHITESPACE)
  list(APPEND API_PYTHON_ENV "LD_PRELOAD=${API_ASAN}:${API_UBSAN}" "ASAN_OPTIONS=detect_leaks=0")
endif()
add_test(NAME api.python COMMAND sh -c "${API_NEEDS_NUMPY}" sh
         ${API_DIR}/test_python.py $<TARGET_FILE:deltri> ${CMAKE_SOURCE_DIR})
set_tests_properties(api.python PROPERTIES ENVIRONMENT "${API_PYTHON_ENV}" SKIP_RETURN_CODE 77 TIMEOUT 300)
add_test(NAME api.size_field COMMAND sh -c "${API_NEEDS_NUMPY}" sh
         ${API_DIR}/size_field.py $<TARGET_FILE:deltri> ${CMAKE_SOURCE_DIR})
set_tests_properties(api.size_field PROPERTIES ENVIRONMENT "${API_PYTHON_ENV}" SKIP_RETURN_CODE 77 TIMEOUT 300)
add_test(NAME api.no_global_state COMMAND sh ${API_DIR}/global_state.sh $<TARGET_FILE:deltri_shared>)
set_tests_properties(api.no_global_state PROPERTIES SKIP_RETURN_CODE 77)
add_test(NAME docs.library_examples COMMAND /usr/bin/python3 ${API_DIR}/library_examples.py ${CMAKE_SOURCE_DIR} ${CMAKE_BINARY_DIR} "${API_SANITIZE_FLAGS}")
set_tests_properties(docs.library_examples PROPERTIES ENVIRONMENT "${API_PYTHON_ENV}" TIMEOUT 600 SKIP_RETURN_CODE 77)
# Facets in 3-D through the library (deltri_mesh_surface, deltri::mesh_surface, deltri.mesh_surface):
# a C and a C++ client on the shared library and the Python module, against the command line's
# files and independent facts (tests/api/surface_clients.py).
add_executable(test_api_surface_c ${API_DIR}/surface_client.c)
set_target_properties(test_api_surface_c PROPERTIES C_STANDARD 99 C_STANDARD_REQUIRED ON C_EXTENSIONS OFF)
target_compile_options(test_api_surface_c PRIVATE -Wall -Wextra -pedantic)
target_link_libraries(test_api_surface_c PRIVATE deltri_shared)
target_include_directories(test_api_surface_c PRIVATE ${CMAKE_SOURCE_DIR}/src/api)
add_executable(test_api_surface_cpp ${API_DIR}/surface_client.cpp)
target_compile_options(test_api_surface_cpp PRIVATE ${DELTRI_WARNINGS})
target_link_libraries(test_api_surface_cpp PRIVATE deltri_shared)
target_include_directories(test_api_surface_cpp PRIVATE ${CMAKE_SOURCE_DIR}/src/api)
add_test(NAME api.surface COMMAND sh -c "/usr/bin/python3 -c 'import numpy' 2>/dev/null || exit 77; exec /usr/bin/python3 \"$@\"" sh
         ${API_DIR}/surface_clients.py $<TARGET_FILE:deltri> $<TARGET_FILE:test_api_surface_c>
         $<TARGET_FILE:test_api_surface_cpp> ${CMAKE_SOURCE_DIR})
set_tests_properties(api.surface PROPERTIES ENVIRONMENT "${API_PYTHON_ENV}" SKIP_RETURN_CODE 77 TIMEOUT 600)
# --range-restricted and --corner-lopping through the library (the letters' words), and the refusal.
add_executable(test_api_paper_options ${API_DIR}/test_paper_options.cpp)
target_compile_options(test_api_paper_options PRIVATE ${DELTRI_WARNINGS})
target_link_libraries(test_api_paper_options PRIVATE deltri_core)
add_test(NAME api.paper_options COMMAND test_api_paper_options)
# One input through the command line, the C library, the C++ library and the Python module: the
# same mesh or the same error class, long options in the switch string included (issue 47).
add_executable(test_api_cross_c ${API_DIR}/cross_client.c)
set_target_properties(test_api_cross_c PROPERTIES C_STANDARD 99 C_STANDARD_REQUIRED ON C_EXTENSIONS OFF)
target_compile_options(test_api_cross_c PRIVATE -Wall -Wextra -pedantic)
target_link_libraries(test_api_cross_c PRIVATE deltri_shared)
target_include_directories(test_api_cross_c PRIVATE ${CMAKE_SOURCE_DIR}/src/api)
add_executable(test_api_cross_cpp ${API_DIR}/cross_client.cpp)
target_compile_options(test_api_cross_cpp PRIVATE ${DELTRI_WARNINGS})
target_link_libraries(test_api_cross_cpp PRIVATE deltri_shared)
target_include_directories(test_api_cross_cpp PRIVATE ${CMAKE_SOURCE_DIR}/src/api)
add_test(NAME api.cross_interface COMMAND sh -c "${API_NEEDS_NUMPY}" sh
         ${API_DIR}/cross_interface.py $<TARGET_FILE:deltri> $<TARGET_FILE:test_api_cross_c>
         $<TARGET_FILE:test_api_cross_cpp>)
set_tests_properties(api.cross_interface PROPERTIES ENVIRONMENT "${API_PYTHON_ENV}" SKIP_RETURN_CODE 77 TIMEOUT 300)
# The `triangle` package's documented examples with `import deltri as tr` (issue 46): every mesh
# through deltri_mesh_verify and the exact checker, plots through matplotlib's Agg backend.
# Skipped (77) without python3-numpy or python3-matplotlib, saying what installs them.
add_test(NAME api.triangle_package COMMAND sh -c "${API_NEEDS_NUMPY}" sh
         ${API_DIR}/triangle_package.py $<TARGET_FILE:deltri> $<TARGET_FILE:deltri_mesh_verify> ${CMAKE_SOURCE_DIR})
set_tests_properties(api.triangle_package PROPERTIES ENVIRONMENT "${API_PYTHON_ENV};MPLBACKEND=Agg" SKIP_RETURN_CODE 77 TIMEOUT 600)
# What a surface mesh is not, reported through the library as the command line warns of it (issue 47).
add_test(NAME api.surface_report COMMAND sh -c "${API_NEEDS_NUMPY}" sh ${API_DIR}/surface_report.py)
set_tests_properties(api.surface_report PROPERTIES ENVIRONMENT "${API_PYTHON_ENV}" SKIP_RETURN_CODE 77 TIMEOUT 300)
