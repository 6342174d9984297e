// chr(1e10) (issue 22): POV-Ray's "Value cannot be used in chr(...)".
// expect: status 2
// expect: error chr-1e10.pov:4:18: chr(1e+10): a character code is from 0 to 65535
#declare S = chr(1e10);
