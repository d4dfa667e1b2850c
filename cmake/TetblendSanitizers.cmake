# ASan + UBSan flags, applied per target by tetblend_project_options().
set(TETBLEND_SANITIZER_FLAGS
    -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
if(TETBLEND_SANITIZE)
  # Propagate to link steps of every target (static libraries get linked into
  # executables that must carry the runtime).
  add_link_options(-fsanitize=address,undefined)
endif()
