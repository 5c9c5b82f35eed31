// The figures of a run, as a table for people and as report.json for scripts.
#pragma once

#include "semimesh/pipeline/config.hpp"
#include "semimesh/pipeline/pipeline.hpp"

#include <string>

namespace semimesh::pipeline {

/// Multi-line table: elements by type and order, boundary groups, min/median scaled Jacobian,
/// invalid count, conformity problems, volume errors, time per stage, peak memory, files.
std::string summary_table(const RunResult& result);

/// One JSON object with the same figures (keys documented in docs/config.md, "report.json").
std::string report_json(const RunResult& result, const Config& config);

}  // namespace semimesh::pipeline
