#include "regress/report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <tuple>

#include "base/atomic_file.h"

namespace proxygi::regress {
namespace {

std::string escape(const std::string& text) {
  std::string out;
  for (char ch : text) {
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += ch;
    }
  }
  return out;
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.4g", value);
  return text;
}

// The metric over frames: a polyline, the threshold dashed, failing points red, the first failing frame marked.
std::string sparkline(const CheckResult& c) {
  if (c.series.empty()) return "";
  const double width = 240, height = 60, pad = 4;
  double top = c.threshold;
  for (const FramePoint& p : c.series) top = std::max(top, p.value);
  if (!(top > 0)) top = 1;
  top *= 1.1;
  const int first = c.series.front().frame, last = c.series.back().frame;
  auto x = [&](int frame) { return pad + (last == first ? 0.5 : double(frame - first) / double(last - first)) * (width - 2 * pad); };
  auto y = [&](double v) { return height - pad - v / top * (height - 2 * pad); };
  std::ostringstream svg;
  svg << "<svg class=\"plot\" width=\"" << width << "\" height=\"" << height << "\" viewBox=\"0 0 " << width << " " << height
      << "\"><title>" << escape(c.metric) << " over frames " << first << ".." << last << "</title>";
  if (c.threshold > 0)
    svg << "<line x1=\"0\" x2=\"" << width << "\" y1=\"" << number(y(c.threshold)) << "\" y2=\"" << number(y(c.threshold))
        << "\" class=\"threshold\"/>";
  svg << "<polyline class=\"metric\" points=\"";
  for (const FramePoint& p : c.series) svg << number(x(p.frame)) << "," << number(y(p.value)) << " ";
  svg << "\"/>";
  for (const FramePoint& p : c.series)
    svg << "<circle cx=\"" << number(x(p.frame)) << "\" cy=\"" << number(y(p.value)) << "\" r=\"2.5\" class=\""
        << (p.failed ? "bad" : "good") << "\"><title>frame " << p.frame << ": " << number(p.value) << "</title></circle>";
  if (c.first_failing_frame >= 0)
    svg << "<line x1=\"" << number(x(c.first_failing_frame)) << "\" x2=\"" << number(x(c.first_failing_frame))
        << "\" y1=\"0\" y2=\"" << height << "\" class=\"first\"/>";
  svg << "</svg>";
  return svg.str();
}

std::string image_cell(const char* label, const std::string& uri) {
  if (uri.empty()) return "";
  return "<figure><img alt=\"" + std::string(label) + "\" src=\"" + uri + "\"><figcaption>" + label + "</figcaption></figure>";
}

constexpr const char* kStyle = R"(body{font:14px system-ui,sans-serif;margin:1.5em;background:#fafafa;color:#222}
.check{background:#fff;border:1px solid #ddd;border-left:6px solid #6a6;margin:.6em 0;padding:.6em .9em}
.check.fail,.check.error,.check.new{border-left-color:#c33}.check.skipped{border-left-color:#aaa}.check.blessed{border-left-color:#36c}
.badge{font-weight:bold;text-transform:uppercase;margin-right:.6em}code{background:#f0f0f0;padding:1px 4px}
figure{display:inline-block;margin:.3em .6em 0 0;text-align:center}img{width:128px;image-rendering:pixelated;border:1px solid #ccc}
.plot .metric{fill:none;stroke:#357;stroke-width:1.5}.plot .threshold{stroke:#c33;stroke-dasharray:4 3}
.plot .first{stroke:#c33;stroke-width:1}.plot .bad{fill:#c33}.plot .good{fill:#357}.hidden{display:none}ul{margin:.3em 0})";

constexpr const char* kScript = R"(window.addEventListener('error',function(e){document.body.dataset.errors=(document.body.dataset.errors||'')+e.message+';'});
function applyFilter(){var only=document.getElementById('failures').checked;
document.querySelectorAll('.check').forEach(function(el){el.classList.toggle('hidden',only&&!el.classList.contains('failure'))});}
window.addEventListener('load',function(){var imgs=Array.prototype.slice.call(document.images);
var ok=imgs.every(function(i){return i.complete&&i.naturalWidth>0});
document.body.dataset.images=imgs.length;document.body.dataset.imagesOk=ok?'true':'false';
document.getElementById('failures').addEventListener('change',applyFilter);applyFilter();});)";

}  // namespace

std::string report_html(const RunResults& results) {
  std::vector<CheckResult> checks = results.checks;
  std::sort(checks.begin(), checks.end(),
            [](const CheckResult& a, const CheckResult& b) { return std::tie(a.scenario, a.check) < std::tie(b.scenario, b.check); });
  int failures = 0;
  for (const CheckResult& c : checks) failures += is_failure(c.outcome);
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>proxygi regress: " << failures
       << " failing</title><style>" << kStyle << "</style></head><body>\n<h1>proxygi regress</h1><p>Device <code>"
       << escape(results.device) << "</code> (family <code>" << escape(results.family) << "</code>): " << checks.size()
       << " checks, " << failures << " failing.</p>\n<label><input type=\"checkbox\" id=\"failures\"" << (failures ? " checked" : "")
       << "> failures only</label>\n";
  for (const CheckResult& c : checks) {
    const std::string outcome(outcome_name(c.outcome));
    html << "<section class=\"check " << outcome << (is_failure(c.outcome) ? " failure" : "") << "\" id=\""
         << escape(c.scenario + "/" + c.check) << "\"><div><span class=\"badge\">" << outcome << "</span><b>"
         << escape(c.scenario) << "/" << escape(c.check) << "</b> <small>(" << escape(c.type)
         << (c.tier.empty() ? "" : ", golden tier " + escape(c.tier)) << ")</small></div><p>" << escape(c.message) << "</p>";
    if (!c.details.empty()) {
      html << "<ul>";
      for (std::size_t i = 0; i < c.details.size() && i < 12; ++i) html << "<li>" << escape(c.details[i]) << "</li>";
      if (c.details.size() > 12) html << "<li>… " << c.details.size() - 12 << " more</li>";
      html << "</ul>";
    }
    if (is_failure(c.outcome)) html << "<p>Bless: <code>" << escape(c.bless_command()) << "</code></p>";
    html << sparkline(c);
    if (c.images) {
      html << "<div>frame " << c.images->frame << ": " << image_cell("golden", c.images->golden) << image_cell("new", c.images->actual)
           << image_cell("difference", c.images->diff) << image_cell("FLIP", c.images->flip) << "</div>";
    }
    html << "</section>\n";
  }
  html << "<script>" << kScript << "</script>\n</body></html>\n";
  return html.str();
}

std::string junit_xml(const RunResults& results) {
  std::vector<CheckResult> checks = results.checks;
  std::sort(checks.begin(), checks.end(),
            [](const CheckResult& a, const CheckResult& b) { return std::tie(a.scenario, a.check) < std::tie(b.scenario, b.check); });
  int failures = 0, skipped = 0;
  for (const CheckResult& c : checks) failures += is_failure(c.outcome), skipped += c.outcome == Outcome::skipped;
  std::ostringstream xml;
  xml << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites><testsuite name=\"proxygi regress\" tests=\"" << checks.size()
      << "\" failures=\"" << failures << "\" skipped=\"" << skipped << "\">\n";
  for (const CheckResult& c : checks) {
    xml << " <testcase classname=\"" << escape(c.scenario) << "\" name=\"" << escape(c.check) << "\">";
    if (is_failure(c.outcome)) {
      xml << "<failure type=\"" << outcome_name(c.outcome) << "\" message=\"" << escape(c.message) << "\">";
      for (const std::string& d : c.details) xml << escape(d) << "\n";
      xml << "bless: " << escape(c.bless_command()) << "</failure>";
    } else if (c.outcome == Outcome::skipped) {
      xml << "<skipped message=\"" << escape(c.message) << "\"/>";
    }
    xml << "</testcase>\n";
  }
  xml << "</testsuite></testsuites>\n";
  return xml.str();
}

Status write_reports(const RunResults& results, const std::filesystem::path& dir) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error) return make_error(dir.string() + ": " + error.message());
  if (Status s = write_file_atomically(dir / "report.html", std::string_view(report_html(results))); !s) return s;
  if (Status s = write_file_atomically(dir / "results.json", std::string_view(to_json(results))); !s) return s;
  if (Status s = write_file_atomically(dir / "junit.xml", std::string_view(junit_xml(results))); !s) return s;
  return write_file_atomically(dir / "timings.json", std::string_view(timings_to_json(results)));
}

}  // namespace proxygi::regress
