# Warnings as the issues ask: -Wall -Wextra -Wpedantic -Wshadow, on our targets only.
# -Wno-restrict: GCC 12 reports a false -Wrestrict inside std::string assignment at -O2/-O3
# (GCC bug 105651); it points at libstdc++, not at our code.
function(catena_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow
                         $<$<AND:$<CXX_COMPILER_ID:GNU>,$<VERSION_LESS:$<CXX_COMPILER_VERSION>,13>>:-Wno-restrict>)
endfunction()
