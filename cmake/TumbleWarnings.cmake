# tumble_set_warnings(target): the project's warning level, and floating-point settings that keep
# results independent of the compiler's choice to fuse multiply-adds.
function(tumble_set_warnings target)
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow
        # Designated initialisers that leave members at their defaults are the intended style.
        -Wno-missing-field-initializers -ffp-contract=off)
    if(TUMBLE_WARNINGS_AS_ERRORS)
        target_compile_options(${target} PRIVATE -Werror)
    endif()
    if(TUMBLE_SANITIZE)
        target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer)
        target_link_options(${target} PRIVATE -fsanitize=address,undefined)
    endif()
endfunction()
