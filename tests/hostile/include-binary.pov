// An include of a file that is no scene (here: itself as a binary, a file
// with a zero byte, written next to it by #write): the read stops at the
// zero byte, with its line and column.
// expect: status 2
// expect: error include-binary.bin:2:3: a zero byte, which no scene text holds: 'include-binary.bin' is not a scene file
#fopen F "include-binary.bin" write
#write (F, "ab\ncd", uint8 0, "ef\n")
#fclose F
#include "include-binary.bin"
