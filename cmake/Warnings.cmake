# Our own targets compile with these warnings and stay clean of them.
function(rasterlab_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wfloat-conversion
    )
endfunction()
