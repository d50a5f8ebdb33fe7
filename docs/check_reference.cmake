# CTest docs.reference: builds the API reference with Doxygen (any warning fails), then checks
# that every name in manual_names.txt (the functions, components and types the user manual
# names) is a documented entry of the reference.
file(REMOVE "${OUTPUT_DIR}/warnings.txt")
execute_process(COMMAND "${DOXYGEN}" "${DOXYFILE}" RESULT_VARIABLE result)
include("${CHECK_WARNINGS}")
if(NOT result EQUAL 0)
  message(FATAL_ERROR "doxygen exited with ${result}")
endif()

file(READ "${OUTPUT_DIR}/xml/index.xml" index)
# Every documented compound and member appears in the index as <name>NAME</name>; compounds
# carry their namespace (edyn::vector3), members do not.
string(REGEX MATCHALL "<name>[^<]*</name>" entries "${index}")
set(known "")
foreach(entry IN LISTS entries)
  string(REGEX REPLACE "^<name>(edyn::)?([^<]*)</name>$" "\\2" name "${entry}")
  list(APPEND known "${name}")
endforeach()
list(REMOVE_DUPLICATES known)

file(STRINGS "${NAMES}" names REGEX "^[^#]")
set(missing "")
foreach(name IN LISTS names)
  string(STRIP "${name}" name)
  if(name STREQUAL "")
    continue()
  endif()
  list(FIND known "${name}" at)
  if(at EQUAL -1)
    list(APPEND missing "${name}")
  endif()
endforeach()
list(LENGTH names total)
if(missing)
  list(JOIN missing "\n  " text)
  message(FATAL_ERROR "Named in the user manual but not in the API reference:\n  ${text}")
endif()
message(STATUS "API reference: no warning; all ${total} names of the manual are documented")
