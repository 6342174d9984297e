// array[1e8] took 22.6 GB (issue 22): the memory budget refuses it at its
// size, before any memory is asked for (here a budget of 1 GiB).
// expect: status 2
// expect: option --max-memory 1G
// expect: error array-1e8.pov:6:20: the scene needs more than 1 GiB of memory while it is parsed (--max-memory sets the budget)
#declare A = array[1e8];
