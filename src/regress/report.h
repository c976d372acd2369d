#pragma once
// Reports of a run: report.html (self-contained: images as data URIs, inline CSS/JS/SVG; per
// check its outcome, message, details, bless command, golden/new/diff/FLIP images and the metric
// over frames with the threshold and the first failing frame; a "failures only" filter),
// results.json (results.h) and junit.xml. All three are deterministic functions of the results
// and hold no measured time; timings.json holds the budget checks' times.
#include <filesystem>
#include <string>

#include "base/result.h"
#include "regress/results.h"

namespace proxygi::regress {

std::string report_html(const RunResults& results);
std::string junit_xml(const RunResults& results);
// Writes DIR/report.html, DIR/results.json, DIR/junit.xml and DIR/timings.json (atomically; DIR is created).
Status write_reports(const RunResults& results, const std::filesystem::path& dir);

}  // namespace proxygi::regress
