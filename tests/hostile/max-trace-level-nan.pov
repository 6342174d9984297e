// max_trace_level NaN (issue 22): refused at the value.
// expect: status 2
// expect: error max-trace-level-nan.pov:5:35: expected a finite number, found nan
#declare N = 0 * 1e309;
global_settings { max_trace_level N }
