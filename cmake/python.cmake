# The figure scripts need matplotlib and numpy, which Debian installs for /usr/bin/python3,
# not for whatever python3 comes first on PATH. Pick the first interpreter that has both.
set(HM_PYTHON "" CACHE FILEPATH "Python interpreter with matplotlib and numpy (auto-detected)")
if(NOT HM_PYTHON)
  foreach(candidate /usr/bin/python3 python3)
    find_program(_hm_py NAMES ${candidate} NO_CACHE)
    if(_hm_py)
      execute_process(COMMAND ${_hm_py} -c "import matplotlib, numpy"
                      RESULT_VARIABLE _hm_py_rc OUTPUT_QUIET ERROR_QUIET)
      if(_hm_py_rc EQUAL 0)
        set(HM_PYTHON ${_hm_py} CACHE FILEPATH "Python interpreter with matplotlib and numpy" FORCE)
        break()
      endif()
    endif()
    unset(_hm_py)
  endforeach()
endif()
if(HM_PYTHON)
  message(STATUS "hmlattice: figures drawn with ${HM_PYTHON}")
else()
  message(WARNING "hmlattice: no python3 with matplotlib+numpy found; reports will list figures as missing. "
                  "Run scripts/install-deps.sh.")
endif()
