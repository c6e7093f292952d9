# Finds the CMake package inside the cantools_od Python package that was installed together with
# this folder (<prefix>/share/cmake/cantools_od): the console script of the same prefix knows where.
# Sets _cantools_od_package_dir, or leaves it empty.
get_filename_component(_cantools_od_prefix "${CMAKE_CURRENT_LIST_DIR}/../../.." ABSOLUTE)
string(MAKE_C_IDENTIFIER "_CANTOOLS_OD_PACKAGE_DIR_${_cantools_od_prefix}" _cantools_od_cache)
set(_cantools_od_package_dir "${${_cantools_od_cache}}")
if(NOT _cantools_od_package_dir OR NOT EXISTS "${_cantools_od_package_dir}/cantools_od.cmake")
  set(_cantools_od_package_dir "")
  foreach(_cantools_od_script IN ITEMS "${_cantools_od_prefix}/bin/cantools-od"
                                       "${_cantools_od_prefix}/Scripts/cantools-od.exe")
    if(EXISTS "${_cantools_od_script}")
      execute_process(COMMAND "${_cantools_od_script}" cmake-dir
                      OUTPUT_VARIABLE _cantools_od_package_dir OUTPUT_STRIP_TRAILING_WHITESPACE
                      RESULT_VARIABLE _cantools_od_result ERROR_QUIET)
      if(NOT _cantools_od_result EQUAL 0 OR NOT EXISTS "${_cantools_od_package_dir}/cantools_od.cmake")
        set(_cantools_od_package_dir "")
      endif()
      break()
    endif()
  endforeach()
  set(${_cantools_od_cache} "${_cantools_od_package_dir}" CACHE INTERNAL "cantools_od CMake package of ${_cantools_od_prefix}")
endif()
