// A fresh SystemC simulation context per run (SystemC allows one elaboration per context); shared
// by the system models in tlm/src.
#pragma once

#include <systemc>

#include <cstdlib>

namespace tu::sysmodel {
struct Context {
  Context() {
    setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
    sc_core::sc_curr_simcontext = new sc_core::sc_simcontext;
    sc_core::sc_default_global_context = sc_core::sc_curr_simcontext;
  }
  ~Context() {
    delete sc_core::sc_curr_simcontext;
    sc_core::sc_curr_simcontext = nullptr;
    sc_core::sc_default_global_context = nullptr;
  }
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
};
}  // namespace tu::sysmodel
