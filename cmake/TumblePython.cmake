# Finds what the Python module needs (python/, issue 18): a Python 3 interpreter that imports
# NumPy, its headers (python3-dev) and pybind11 (pybind11-dev). Sets TUMBLE_PYTHON_FOUND.
#
# A python3 earlier on PATH without NumPy (a pyenv shim, say) is passed over for one that has it
# (Debian's /usr/bin/python3 with python3-numpy): the module and its tests must run in the same
# interpreter as NumPy. -DPython3_EXECUTABLE=... chooses one explicitly (setup.py passes its own).

function(tumble_python_imports_numpy result candidate)
    execute_process(COMMAND "${candidate}" -c "import numpy"
        RESULT_VARIABLE status OUTPUT_QUIET ERROR_QUIET)
    if(NOT status EQUAL 0)
        set(${result} FALSE PARENT_SCOPE)
    endif()
endfunction()

if(NOT Python3_EXECUTABLE)
    find_program(TUMBLE_PYTHON_WITH_NUMPY NAMES python3 VALIDATOR tumble_python_imports_numpy)
    if(TUMBLE_PYTHON_WITH_NUMPY)
        set(Python3_EXECUTABLE "${TUMBLE_PYTHON_WITH_NUMPY}" CACHE FILEPATH
            "The Python the tumble module is built for")
    endif()
endif()
find_package(Python3 3.9 COMPONENTS Interpreter Development.Module QUIET)
if(Python3_FOUND)
    find_package(pybind11 2.6 CONFIG QUIET)
endif()
if(Python3_FOUND AND pybind11_FOUND)
    set(TUMBLE_PYTHON_FOUND ON)
else()
    set(TUMBLE_PYTHON_FOUND OFF)
endif()
