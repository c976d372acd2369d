#pragma once
// proxygi compare --sequence TEST_DIR REFERENCE_DIR --frames A:B [--scene SCENE] [--json]: the
// temporal metrics (study/sequence_temporal.h) of TEST_DIR/frame_%05d.exr (record --exr) against
// REFERENCE_DIR/frame_%05d.exr (proxygi reference per frame), with exact reprojection traced
// from the scene. Missing or mismatched frames and a bad scene exit 2.
#include <string>

namespace proxygi::app {

struct SequenceCompareArgs {
  std::string test_dir, reference_dir;
  std::string frames;  // "A:B", inclusive
  std::string scene;   // as record's SCENE (empty: default)
  bool json = false;
};
int run_compare_sequence(const SequenceCompareArgs& args);

}  // namespace proxygi::app
