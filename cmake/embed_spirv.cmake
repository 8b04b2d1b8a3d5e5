# cmake -DINPUT=x.spv -DOUTPUT=x.spv.h -DNAME=spirv_x -P embed_spirv.cmake
#
# Writes a SPIR-V binary as `const uint32_t NAME[] = {...};`, the form glslang's --vn writes, so
# the code that includes it is the same whether or not the module went through spirv-opt. SPIR-V
# files are little-endian words (spirv-opt writes the host's order, and every supported host is
# little-endian), so each word's four bytes are reversed into one hexadecimal literal.
file(READ ${INPUT} hex HEX)
string(LENGTH "${hex}" length)
math(EXPR remainder "${length} % 8")
if(length EQUAL 0 OR NOT remainder EQUAL 0)
  message(FATAL_ERROR "${INPUT}: not a whole number of 32-bit words")
endif()
string(REGEX REPLACE "(..)(..)(..)(..)" "0x\\4\\3\\2\\1," words "${hex}")
set(word "0x........,")
string(REGEX REPLACE "(${word}${word}${word}${word}${word}${word}${word}${word})" "\\1\n" words "${words}")
file(WRITE ${OUTPUT}.tmp "#pragma once\n#include <cstdint>\nconst uint32_t ${NAME}[] = {\n${words}\n};\n")
file(RENAME ${OUTPUT}.tmp ${OUTPUT})
