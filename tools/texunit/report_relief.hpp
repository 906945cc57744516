// Relief (B4) rows and the quality-against-cost plot of `texunit report` (docs/blocks/relief.md).
#pragma once

#include <string>
#include <vector>

#include "report.hpp"
#include "texunit/output.hpp"

namespace tu::report {

// Blocks reported here: pom_layers, pom_march, iter_parallax, pom_unit (pom_unit also gives the
// rows of its stages pom_setup and pom_refine).
bool is_relief_block(const std::string& block);

// Errors and RTL throughput from Verilator runs (random set for fixed-latency blocks; the bricks
// scene stream for the data-dependent engines, whose ii_cycles is the measured mean cycles per
// pixel); the report adds the area from its Yosys cache.
std::vector<Row> relief_rows(const std::vector<std::string>& blocks, const std::string& root);  // root: the docs scenes (afvis)

// PSNR against march steps per pixel and against cycles per pixel (texunit relief-quality data,
// fixed N 4..32, adaptive, iterative, per view angle): DIR/relief_quality.dat, .gp and
// relief_psnr_vs_steps.png, relief_psnr_vs_cycles.png (gnuplot). Returns false if gnuplot failed.
bool relief_plot(const std::string& dir, out::Outputs& outs);

}  // namespace tu::report
