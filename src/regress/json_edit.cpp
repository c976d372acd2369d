#include "regress/json_edit.h"

#include <algorithm>
#include <cctype>
#include <map>

namespace proxygi::regress {
namespace {

struct Member {
  std::string key;
  std::size_t value_begin = 0, value_end = 0;  // [begin, end) of the value's text
};

// A minimal JSON scanner: positions of members, no values decoded (scenario files are JSON
// without comments; nlohmann has validated them before any edit).
class Scanner {
 public:
  explicit Scanner(std::string_view text) : text_(text) {}

  void space() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
  }
  bool peek(char c) {
    space();
    return at_ < text_.size() && text_[at_] == c;
  }
  bool take(char c) {
    if (!peek(c)) return false;
    ++at_;
    return true;
  }
  bool string(std::string* out) {
    if (!take('"')) return false;
    std::string value;
    while (at_ < text_.size() && text_[at_] != '"') {
      if (text_[at_] == '\\') value += text_[at_++];
      if (at_ < text_.size()) value += text_[at_++];
    }
    if (at_ >= text_.size()) return false;
    ++at_;
    if (out) *out = value;
    return true;
  }
  bool value() {
    space();
    if (at_ >= text_.size()) return false;
    const char c = text_[at_];
    if (c == '"') return string(nullptr);
    if (c == '{' || c == '[') {
      const char close = c == '{' ? '}' : ']';
      ++at_;
      if (take(close)) return true;
      do {
        if (c == '{' && !(string(nullptr) && take(':'))) return false;
        if (!value()) return false;
      } while (take(','));
      return take(close);
    }
    const std::size_t start = at_;
    while (at_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[at_])) || std::string_view("+-.").find(text_[at_]) != std::string_view::npos))
      ++at_;
    return at_ > start;
  }
  // The members of the object starting here; `close` = the position of its '}'.
  bool object(std::vector<Member>& members, std::size_t& close) {
    if (!take('{')) return false;
    if (!peek('}')) {
      do {
        Member m;
        if (!string(&m.key) || !take(':')) return false;
        space();
        m.value_begin = at_;
        if (!value()) return false;
        m.value_end = at_;
        members.push_back(std::move(m));
      } while (take(','));
    }
    space();
    close = at_;
    return take('}');
  }
  std::size_t at() const { return at_; }
  void seek(std::size_t at) { at_ = at; }

 private:
  std::string_view text_;
  std::size_t at_ = 0;
};

std::vector<std::string_view> lines_of(std::string_view text) {
  std::vector<std::string_view> lines;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) {
      if (start < text.size()) lines.push_back(text.substr(start));
      break;
    }
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

}  // namespace

Result<std::string> edit_check_fields(std::string_view text, const std::vector<FieldEdit>& edits) {
  Scanner top(text);
  std::vector<Member> members;
  std::size_t close = 0;
  if (!top.object(members, close)) return make_error("not a JSON object");
  const auto checks = std::find_if(members.begin(), members.end(), [](const Member& m) { return m.key == "checks"; });
  if (checks == members.end()) return make_error("no \"checks\" array");
  // Each check's members, in file order.
  std::vector<std::pair<std::vector<Member>, std::size_t>> objects;
  Scanner array(text);
  array.seek(checks->value_begin);
  if (!array.take('[')) return make_error("\"checks\" is not an array");
  if (!array.peek(']')) {
    do {
      std::vector<Member> check;
      std::size_t end = 0;
      if (!array.object(check, end)) return make_error("checks[" + std::to_string(objects.size()) + "] is not an object");
      objects.emplace_back(std::move(check), end);
    } while (array.take(','));
  }
  // Replacements as (position, length removed, text), applied from the end of the file back.
  struct Splice {
    std::size_t at, length;
    std::string text;
  };
  std::vector<Splice> splices;
  std::map<std::size_t, std::string> appended;  // check -> ", \"key\": value" members to add
  for (const FieldEdit& edit : edits) {
    if (edit.check >= objects.size())
      return make_error("checks[" + std::to_string(edit.check) + "]: beyond the " + std::to_string(objects.size()) + " checks");
    const auto& [check, end] = objects[edit.check];
    const auto found = std::find_if(check.begin(), check.end(), [&](const Member& m) { return m.key == edit.key; });
    if (found != check.end())
      splices.push_back({found->value_begin, found->value_end - found->value_begin, edit.value});
    else {
      std::string& added = appended[edit.check];
      added.append(check.empty() && added.empty() ? "\"" : ", \"").append(edit.key).append("\": ").append(edit.value);
    }
  }
  for (const auto& [index, members_text] : appended) {
    const auto& [check, end] = objects[index];
    splices.push_back({check.empty() ? end : check.back().value_end, 0, members_text});
  }
  std::sort(splices.begin(), splices.end(), [](const Splice& a, const Splice& b) { return a.at > b.at; });
  std::string out(text);
  for (const Splice& s : splices) out.replace(s.at, s.length, s.text);
  return out;
}

std::string line_diff(std::string_view before, std::string_view after, const std::string& name) {
  const auto a = lines_of(before), b = lines_of(after);
  std::string out;
  for (std::size_t i = 0; i < std::max(a.size(), b.size()); ++i) {
    const std::string_view old_line = i < a.size() ? a[i] : std::string_view(), new_line = i < b.size() ? b[i] : std::string_view();
    if (old_line == new_line) continue;
    if (out.empty()) out.append("--- ").append(name).append("\n+++ ").append(name).append("\n");
    out.append("@@ line ").append(std::to_string(i + 1)).append(" @@\n");
    if (i < a.size()) out.append("-").append(old_line).append("\n");
    if (i < b.size()) out.append("+").append(new_line).append("\n");
  }
  return out;
}

}  // namespace proxygi::regress
