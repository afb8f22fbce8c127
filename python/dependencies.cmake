# What the Python module needs: the Python interpreter of Python_EXECUTABLE (by default the
# first python3 CMake finds; scripts/python.sh passes Debian's /usr/bin/python3) with its
# headers, and pybind11, which then builds for that Python (its FindPython mode).
# Sets SFE_PYTHON_DEPENDENCIES_FOUND, the default of SFE_BUILD_PYTHON.
find_package(Python 3 COMPONENTS Interpreter Development.Module QUIET)
if(Python_FOUND)
  find_package(pybind11 2.6 CONFIG QUIET)
endif()
if(Python_FOUND AND pybind11_FOUND)
  set(SFE_PYTHON_DEPENDENCIES_FOUND ON)
else()
  set(SFE_PYTHON_DEPENDENCIES_FOUND OFF)
endif()
