# Installs the VVM build tree into a scratch prefix, then configures, builds and
# runs the consumer project against it with find_package(VVM).
# -D: VVM_BINARY_DIR, CONSUMER_SOURCE_DIR, WORK_DIR, CMAKE_BUILD_TYPE, and CCACHE_PROGRAM
# with CCACHE_BASEDIR when VVM compiles through ccache (the consumer then does too);
# PYTHON3 and PYTHON_SITE_DIR (relative to the prefix) when the Python module is built: it is
# imported from the prefix and meshes a cube
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
set(launcher)
if(CCACHE_PROGRAM)
  set(ENV{CCACHE_BASEDIR} ${CCACHE_BASEDIR})
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${CCACHE_PROGRAM})
endif()
run(${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${WORK_DIR}/build
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE} ${launcher})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(${WORK_DIR}/build/consumer)
if(PYTHON_SITE_DIR)
  # (no semicolon in the script: run() takes its arguments as a CMake list)
  set(ENV{PYTHONPATH} ${prefix}/${PYTHON_SITE_DIR})
  run(${PYTHON3} -c "
import vvm
print('vvm', vvm.__version__, 'from', vvm.__file__)
assert vvm.__file__.startswith('${prefix}/')
print(vvm.quality(vvm.tet_mesh('${DATA_DIR}/cube.off', vertices=300))['tetrahedra'], 'tetrahedra')
")
endif()
message(STATUS "consumer built and ran against ${prefix}")
