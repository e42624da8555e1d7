# Strict warnings for the project's own targets (user models are compiled
# elsewhere, with warnings shown but never as errors).
function(vv_strict_warnings target)
  target_compile_options(${target} PRIVATE
    -Wall -Wextra -Wshadow -Wnon-virtual-dtor -Wpedantic -Werror)
endfunction()
