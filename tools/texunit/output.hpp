// The CLI's name for the one checked output path (texunit/output.hpp, shared with the library
// writers): every output file of a command goes through tu::cli::Outputs.
#pragma once

#include "texunit/output.hpp"

namespace tu::cli {

using Outputs = tu::out::Outputs;
using tu::out::fs_message;

}  // namespace tu::cli
