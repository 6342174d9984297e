// An endless #while that includes a file: the file is read once, and its
// text counts as text read again at every later #include (a loop whose
// body is an #include read two tokens a pass, and ran for ever).
// expect: status 2
// expect: error include-endless.inc:1697:2: more than 20000000 tokens read again by loops and macro calls (--max-repeated-tokens): is the #while at include-endless.pov:6 endless?
#while (1)
  #include "include-endless.inc"
#end
