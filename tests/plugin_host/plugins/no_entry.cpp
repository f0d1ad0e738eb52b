// Exports nothing: a shared library that is not a plugin.
int no_entry_answer();
int no_entry_answer() { return 42; }
