# hm_warnings(target): the project's warning set, applied to our own targets only.
add_library(hm_warnings INTERFACE)
target_compile_options(hm_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion-null)
