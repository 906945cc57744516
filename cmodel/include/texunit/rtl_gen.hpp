// Generated RTL sources: the SystemVerilog package of shared formats and the coefficient ROMs,
// written from the C model's own constants and tables so that a width or a coefficient changes in
// one place. `texunit gen-rtl` writes them; the test GeneratedRtl.IsFresh compares them with the
// committed files.
#pragma once

#include <map>
#include <string>

namespace tu {

// Relative path (under the repository root) -> file content.
std::map<std::string, std::string> generated_rtl();

}  // namespace tu
