# cmake -DPINS=<pin file> -DCOPY=<copy> -P cantools_od_pins.cmake
#
# Keeps COPY equal to the pin file, and empty while there is none (an empty pin file pins nothing,
# like a missing one). COPY is written only when that changes, so the generation step, which depends
# on COPY, runs exactly once after a pin file appears, changes or goes away, and never otherwise.
if(EXISTS "${PINS}" AND NOT IS_DIRECTORY "${PINS}")
  file(READ "${PINS}" _pins)
else()
  set(_pins "")
endif()
set(_copy "<none>")
if(EXISTS "${COPY}")
  file(READ "${COPY}" _copy)
endif()
if(NOT _copy STREQUAL _pins)
  file(WRITE "${COPY}" "${_pins}")
endif()
