// Lint waivers (Verilator) for linting all of rtl/ in one command (`verilator --lint-only -Wall`
// over every file: the test RtlTools.ParseInEveryTool, `scripts/rtl_tools.sh verilator`). rtl/
// holds many independent block tops by design (each is co-simulated and synthesised on its own),
// so several top-level modules in one run is expected. Only that rule is waived; each block top
// also lints clean alone. Not part of any synthesis or simulation file list (rtl/manifest.json
// "lint_only").
`verilator_config
lint_off -rule MULTITOP
