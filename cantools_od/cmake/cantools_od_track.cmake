# cmake -DTRACKED=<file> -DCOPY=<copy> -P cantools_od_track.cmake
#
# Keeps COPY equal to TRACKED, an optional input of generation beside the EDS (the pin file, the
# canopennode settings), and empty while there is none (an empty file says nothing, like a missing
# one). COPY is written only when that changes, so the generation step, which depends on COPY, runs
# exactly once after the file appears, changes or goes away, and never otherwise.
if(EXISTS "${TRACKED}" AND NOT IS_DIRECTORY "${TRACKED}")
  file(READ "${TRACKED}" _tracked)
else()
  set(_tracked "")
endif()
set(_copy "<none>")
if(EXISTS "${COPY}")
  file(READ "${COPY}" _copy)
endif()
if(NOT _copy STREQUAL _tracked)
  file(WRITE "${COPY}" "${_tracked}")
endif()
