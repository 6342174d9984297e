// Exponential recursion, 2^60 calls, each shallow (issue 22: still running
// after 60 s at 3 GB): the budget of text read again by macro calls stops it.
// expect: status 2
// expect: error macro-exponential.pov:9:1: more than 20000000 tokens read again by loops and macro calls (--max-repeated-tokens): is the recursion of macro 'M' endless?
#macro M(N)
  #if (N > 0)
    M(N - 1) M(N - 1)
  #end
#end
M(60)
