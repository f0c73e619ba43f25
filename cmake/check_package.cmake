# The installed package, checked as a user meets it: `cmake --install` of this build into a
# fresh prefix, then tests/package/consumer configured with find_package(fastshade CONFIG),
# built and run. Run as a test:
#   cmake -DSOURCE_DIR=<repo> -DBUILD_DIR=<build> -DWORK_DIR=<scratch> -P cmake/check_package.cmake
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}")
  endif()
  message(STATUS "${out}")
endfunction()
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(path include/fastshade/render.h lib/libfastshade.a lib/cmake/fastshade/fastshadeConfig.cmake bin/fastshade
             lib/fastshade/libfastshade_oiio.so)
  if(NOT EXISTS ${prefix}/${path})
    message(FATAL_ERROR "the install tree lacks ${path}")
  endif()
endforeach()
if(EXISTS ${prefix}/include/core OR EXISTS ${prefix}/include/exec)
  message(FATAL_ERROR "the install tree holds internal headers (src/)")
endif()
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/package/consumer -B ${WORK_DIR}/build -G Ninja
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix})
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(${WORK_DIR}/build/consumer)
# The installed program writes PNG itself and TIFF through the plugin.
run(${prefix}/bin/fastshade render -o ${WORK_DIR}/default.png)
run(${prefix}/bin/fastshade render -o ${WORK_DIR}/default.tif)
