# VV_SANITIZE=ON instruments everything built here with ASan and UBSan;
# any report aborts the test that triggered it.
if(VV_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all
                      -fno-omit-frame-pointer -g)
  add_link_options(-fsanitize=address,undefined)
endif()
