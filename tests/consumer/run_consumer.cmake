# Script for the consumer.find_package test (cmake -P). Inputs: TUMBLE_BUILD_DIR, CONSUMER_SOURCE_DIR,
# WORK_DIR, CONSUMER_GENERATOR, CONSUMER_CXX_COMPILER, CONSUMER_BUILD_TYPE.
cmake_minimum_required(VERSION 3.25)

foreach(input TUMBLE_BUILD_DIR CONSUMER_SOURCE_DIR WORK_DIR CONSUMER_GENERATOR CONSUMER_CXX_COMPILER)
    if(NOT DEFINED ${input} OR "${${input}}" STREQUAL "")
        message(FATAL_ERROR "run_consumer.cmake: ${input} is not set")
    endif()
endforeach()
if(NOT CONSUMER_BUILD_TYPE)
    set(CONSUMER_BUILD_TYPE Release)
endif()

set(prefix "${WORK_DIR}/prefix")
set(build "${WORK_DIR}/build")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

# runs one command, stops the test with its output when it fails
function(run_step name)
    execute_process(COMMAND ${ARGN}
        RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "consumer test: ${name} failed (${result}):\n${output}")
    endif()
    string(STRIP "${output}" output)
    if(name STREQUAL "run")
        message(STATUS "consumer test: ${name}: ok: ${output}")
    else()
        message(STATUS "consumer test: ${name}: ok")
    endif()
endfunction()

# install everything the build tree installs (all components)
run_step("install" ${CMAKE_COMMAND} --install "${TUMBLE_BUILD_DIR}" --prefix "${prefix}"
    --config "${CONSUMER_BUILD_TYPE}")
if(NOT EXISTS "${prefix}/lib/cmake/tumble/tumbleConfig.cmake"
   AND NOT EXISTS "${prefix}/lib64/cmake/tumble/tumbleConfig.cmake")
    file(GLOB_RECURSE configs "${prefix}/*Config.cmake")
    message(FATAL_ERROR "consumer test: no tumbleConfig.cmake installed (found: ${configs})")
endif()

# configure and build the consumer against the installed package only
run_step("configure" ${CMAKE_COMMAND} -S "${CONSUMER_SOURCE_DIR}" -B "${build}"
    -G "${CONSUMER_GENERATOR}"
    -DCMAKE_CXX_COMPILER=${CONSUMER_CXX_COMPILER}
    -DCMAKE_BUILD_TYPE=${CONSUMER_BUILD_TYPE}
    -DCMAKE_PREFIX_PATH=${prefix}
    -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON)
run_step("build" ${CMAKE_COMMAND} --build "${build}" --config "${CONSUMER_BUILD_TYPE}")

# run it: it exits 0 only if the body fell
find_program(consumer_exe consumer PATHS "${build}" "${build}/${CONSUMER_BUILD_TYPE}" NO_DEFAULT_PATH)
if(NOT consumer_exe)
    message(FATAL_ERROR "consumer test: the consumer executable was not built in ${build}")
endif()
run_step("run" "${consumer_exe}")
