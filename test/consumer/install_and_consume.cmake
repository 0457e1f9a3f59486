# Installs the VVM build tree into a scratch prefix, then configures, builds and
# runs the consumer project against it with find_package(VVM).
# -D: VVM_BINARY_DIR, CONSUMER_SOURCE_DIR, WORK_DIR, CMAKE_BUILD_TYPE
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
function(run)
  execute_process(COMMAND ${ARGV} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGV}")
  endif()
endfunction()
run(${CMAKE_COMMAND} --install ${VVM_BINARY_DIR} --prefix ${prefix})
if(NOT EXISTS ${prefix}/include/CGAL/GSM_mesh_optimization/tetrahedron_quality.h)
  message(FATAL_ERROR "the headers were not installed")
endif()
run(${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${WORK_DIR}/build
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(${WORK_DIR}/build/consumer)
message(STATUS "consumer built and ran against ${prefix}")
