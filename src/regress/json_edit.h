#pragma once
// In-place edits of a scenario file's checks (`regress --calibrate N --write`): the file keeps its
// hand-written layout byte for byte except the values edited, so the diff a person reviews shows
// only the tolerances that changed.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "base/result.h"

namespace proxygi::regress {

struct FieldEdit {
  std::size_t check = 0;  // index into the top-level "checks" array
  std::string key;        // e.g. "pixel_threshold"
  std::string value;      // JSON text of the new value, e.g. "2" or "0.0005"
};

// Replaces each edited key's value text in checks[check], or appends `, "key": value` after the
// object's last member when the key is absent. Errors: text that is not a JSON object with a
// "checks" array, or a check index beyond it.
Result<std::string> edit_check_fields(std::string_view text, const std::vector<FieldEdit>& edits);

// The lines that differ between two texts of the same line count, as "-old" / "+new" pairs
// under a "--- name" / "+++ name" header with "@@ line N @@" markers; "" when equal.
std::string line_diff(std::string_view before, std::string_view after, const std::string& name);

}  // namespace proxygi::regress
