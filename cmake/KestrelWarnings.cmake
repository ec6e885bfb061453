# Our own targets build with warnings as errors; dependencies are included as SYSTEM headers.
add_library(kestrel_warnings INTERFACE)
target_compile_options(kestrel_warnings INTERFACE -Wall -Wextra -Werror)
# GCC warns of a class holding a member of an anonymous namespace's type unless both are in the
# main file. A unity build includes each .cpp into a batch file, so a source file's private
# types would all be reported: the warning is for headers, and a .cpp is not one.
if(KESTREL_UNITY_BUILD AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  target_compile_options(kestrel_warnings INTERFACE -Wno-subobject-linkage)
endif()
