// An endless #while with a heavy body (issue 22: stopped by the loop limit
// only after 106 s): the budget counts the text read, not the iterations.
// expect: status 2
// expect: error while-heavy.pov:8:45: more than 20000000 tokens read again by loops and macro calls (--max-repeated-tokens): is the #while at while-heavy.pov:6 endless?
#declare I = 0;
#while (1)
  #declare I = I + 1;
  #declare J = sin(I) * cos(I) + sqrt(abs(I)) + I * I / (I + 1) - pow(I, 0.5) * exp(-I) + max(I, 1, 2);
#end
