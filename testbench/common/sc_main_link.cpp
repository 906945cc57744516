// libsystemc.so refers to sc_main; programs that use only SystemC's data types (sc_fixed) with
// their own main() still have to define it. It is never called.
extern "C" int sc_main(int, char**) { return 0; }
