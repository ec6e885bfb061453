# Our own targets build with warnings as errors; dependencies are included as SYSTEM headers.
add_library(kestrel_warnings INTERFACE)
target_compile_options(kestrel_warnings INTERFACE -Wall -Wextra -Werror)
