// The report's `filters` group (docs/blocks/feline.md, "the architect's table"): every filter of
// the unit and Feline at probe caps 2..16 on the default scene and the docs scenes, quality
// against clocks per pixel, with the engines' area from the report's Yosys cache.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "report.hpp"
#include "texunit/output.hpp"

namespace tu::report {

// Rows: block "filters", variant = filter, scheme = scene; ii_cycles = clocks per pixel (the RTL
// unit's exact cycle model), latency -1 (kept off the error-vs-cost Pareto plots: quality here
// is a PSNR, higher is better); PSNR, probes, texels in extra_json. `area` fills an engine row's
// cells from the Yosys cache (rows whose rtl_top is set).
std::vector<Row> filter_rows(const std::string& root, const std::function<void(Row&)>& area);

// The markdown section body (table + plot link) and the plot DIR/filters_psnr_vs_clocks.png.
std::string filters_markdown(const std::vector<Row>& rs, const std::string& plot_rel);
// The plot's files go to `outs` (published for gnuplot); returns "" or why gnuplot failed.
std::string filters_plot(const std::vector<Row>& rs, const std::string& dir, out::Outputs& outs);

}  // namespace tu::report
