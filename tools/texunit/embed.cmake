# cmake -DIN=FILE -DOUT=FILE.cpp -DNAME=symbol -P embed.cmake: FILE's bytes as
# `extern const char NAME[]` (NUL-terminated) and `extern const unsigned long NAME_size`.
file(READ ${IN} hex HEX)
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${hex}")
string(REGEX REPLACE "(0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,0x..,)" "\\1\n" bytes "${bytes}")
string(LENGTH "${hex}" n)
math(EXPR n "${n} / 2")
file(WRITE ${OUT}.new "// Generated from ${IN} by embed.cmake: do not edit.\nextern const char ${NAME}[] = {\n${bytes}0x00};\nextern const unsigned long ${NAME}_size = ${n};\n")
file(COPY_FILE ${OUT}.new ${OUT} ONLY_IF_DIFFERENT)
file(REMOVE ${OUT}.new)
