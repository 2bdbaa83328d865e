# The header-only dependencies of the WebAssembly build (tools/build-web.sh, docs/web.md).
# Debian's emscripten compiles against its own libc; putting all of /usr/include on its path would
# shadow that libc, so the build sees only glm, toml++ and Boost through a folder of symlinks,
# and find_package answers for them with targets on that folder instead of searching the host.

set(tumble_web_include "${CMAKE_BINARY_DIR}/web-include")
file(MAKE_DIRECTORY "${tumble_web_include}")
foreach(header_dir glm toml++ boost)
    if(NOT EXISTS "/usr/include/${header_dir}")
        message(FATAL_ERROR "web build: /usr/include/${header_dir} is missing "
                            "(bash tools/install-deps.sh installs it)")
    endif()
    file(CREATE_LINK "/usr/include/${header_dir}" "${tumble_web_include}/${header_dir}" SYMBOLIC)
endforeach()

foreach(target glm::glm tomlplusplus::tomlplusplus Boost::headers)
    add_library(${target} INTERFACE IMPORTED)
    set_target_properties(${target} PROPERTIES
        INTERFACE_SYSTEM_INCLUDE_DIRECTORIES "${tumble_web_include}"
        INTERFACE_INCLUDE_DIRECTORIES "${tumble_web_include}")
endforeach()

# The three packages above are answered here; OpenMP, MPI and Python do not exist for the web
# build (their users fall back to one thread or are off), everything else is searched as usual.
set(tumble_web_provided glm tomlplusplus Boost)
set(tumble_web_absent OpenMP MPI Python Python3 pybind11)
macro(find_package package_name)
    if("${package_name}" IN_LIST tumble_web_provided)
        set(${package_name}_FOUND TRUE)
    elseif("${package_name}" IN_LIST tumble_web_absent)
        set(${package_name}_FOUND FALSE)
        set(${package_name}_CXX_FOUND FALSE)
    else()
        _find_package(${ARGV})
    endif()
endmacro()

# Scenario errors are C++ exceptions (toml++ and ScenarioError): WebAssembly exception handling
# costs nothing on the path that does not throw, unlike the JavaScript emulation.
add_compile_options(-fwasm-exceptions)
add_link_options(-fwasm-exceptions)
