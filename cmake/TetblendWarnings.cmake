# tetblend_project_options(<target>): warnings as errors on the project's own
# code only (third-party headers come in as SYSTEM), plus the sanitizers when
# TETBLEND_SANITIZE is on.
function(tetblend_project_options target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Werror)
  if(TETBLEND_SANITIZE)
    target_compile_options(${target} PRIVATE ${TETBLEND_SANITIZER_FLAGS})
    target_link_options(${target} PRIVATE ${TETBLEND_SANITIZER_FLAGS})
  endif()
endfunction()
