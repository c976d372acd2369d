#pragma once
// Viewer scripts (`proxygi view --script FILE.json`): time-stamped input events run on a fixed
// time step against the viewer core, the same events a person's keys and mouse produce.
//
//   {"step_s": 0.0416667,                        // optional; default 1 / scene fps
//    "events": [
//      {"t": 0.0, "key": "space"},               // key names: input.h (shift/ctrl: true)
//      {"t": 0.5, "drag": {"button": "left", "dx": 40, "dy": -10}},
//      {"t": 0.5, "scroll": 2},
//      {"t": 1.0, "set": {"sh_order": 5, "receiver_scale": 2, "tonemap": "reinhard"}},
//      {"t": 1.5, "screenshot": "out/a.png", "ui": false},
//      {"t": 2.0, "open": "model.glb"}, {"t": 2.0, "save": "out/seen.json"},
//      {"t": 2.5, "resize": [320, 200]}, {"t": 3, "minimize": true}, {"t": 3.5, "restore": true},
//      {"t": 3.7, "move": [1400, 100]},          // the window's top-left (another screen)
//      {"t": 4.0, "quit": true}]}
//
// Script time advances by step_s per rendered frame and stands still while a scene loads or
// while events at the current time remain (after a screenshot), so a run is deterministic. Events at the same time keep their order. The script ends (and the
// viewer quits) after its last event unless that event keeps it open ("quit": false is an error).
#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

#include "base/result.h"
#include "view/input.h"

namespace proxygi::view {

struct TimedEvent {
  double time_s = 0.0;
  Event event;
};

struct Script {
  std::optional<double> step_s;
  std::vector<TimedEvent> events;  // sorted by time, stable
};

// Errors name the event index and field ("events[3].key: unknown key \"spce\"").
Result<Script> parse_script(std::string_view json_text);
Result<Script> load_script(const std::filesystem::path& file);

// Hands out a script's events as its clock passes them.
class ScriptPlayer {
 public:
  explicit ScriptPlayer(Script script) : script_(std::move(script)) {}
  // The events due at script time `now_s`, in order, up to and including the first screenshot:
  // a screenshot shows the frame as the events before it left it, and the events after it
  // (even at the same time) apply from the next frame on.
  std::vector<Event> due(double now_s);
  bool has_due(double now_s) const;
  bool finished() const { return next_ >= script_.events.size(); }
  const Script& script() const { return script_; }

 private:
  Script script_;
  std::size_t next_ = 0;
};

}  // namespace proxygi::view
