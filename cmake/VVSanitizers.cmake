# VV_SANITIZE=ON instruments everything built here with ASan and UBSan;
# any report aborts the test that triggered it. Line tables (-g1, after the
# build type's -g) are all a sanitizer report needs for file:line stacks,
# and they build much faster than full debug information.
if(VV_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all
                      -fno-omit-frame-pointer -g1)
  add_link_options(-fsanitize=address,undefined)
endif()
