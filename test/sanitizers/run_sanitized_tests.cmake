# The sanitizer stage (CTest test sanitizer.address_undefined, test/CMakeLists.txt): configures
# a second build folder with VVM_SANITIZE=<SANITIZE>, builds the test programs labelled
# `sanitized` there (through the compiler cache the main build uses) and runs their tests.
# A report of ASan, UBSan or LSan stops the test program (halt_on_error=1, options from the
# top CMakeLists.txt) and fails this test; the suppressed reports, all in other projects'
# headers, are listed with their reasons in test/sanitizers/*.supp.
#   cmake -DSOURCE_DIR=<src> -DBINARY_DIR=<dir> -DSANITIZE=address,undefined
#         [-DCMAKE_BUILD_TYPE=Release] [-DCMAKE_CXX_COMPILER=g++] -P run_sanitized_tests.cmake
foreach(var SOURCE_DIR BINARY_DIR SANITIZE)
  if(NOT ${var})
    message(FATAL_ERROR "run_sanitized_tests.cmake: -D${var}=... is needed")
  endif()
endforeach()
if(NOT CMAKE_BUILD_TYPE)
  set(CMAKE_BUILD_TYPE Release)
endif()

function(run_step what)
  message(STATUS "sanitizer stage: ${what}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "sanitizer stage: ${what} failed (${result})")
  endif()
endfunction()

set(configure ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${BINARY_DIR} -DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE}
    -DVVM_SANITIZE=${SANITIZE} -DVVM_TEST_SANITIZERS=OFF -DVVM_BUILD_EXAMPLES=OFF
    -DVVM_BUILD_BENCHMARKS=OFF -DVVM_BUILD_TOOLS=OFF -DVVM_BUILD_PYTHON=OFF)
if(CMAKE_CXX_COMPILER)
  list(APPEND configure -DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER})
endif()
run_step("configure ${BINARY_DIR} with -fsanitize=${SANITIZE}" ${configure})
run_step("build the sanitized tests" ${CMAKE_COMMAND} --build ${BINARY_DIR} -j2 --target vvm_sanitized_tests)
run_step("run the sanitized tests"
         ${CMAKE_CTEST_COMMAND} --test-dir ${BINARY_DIR} -L sanitized -j2 --output-on-failure --no-tests=error)
