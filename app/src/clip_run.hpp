// The work of `hlr clip`, once per kernel: build the polygons, clip, check areas, write hlr-clip/1.
// Each kernel is instantiated in its own translation unit (clip_run_<kernel>.cpp).
#pragma once

#include "polygon_json.hpp"

#include <iosfwd>
#include <string>
#include <vector>

namespace hlr::app {

struct ClipJob {
  std::string subject_path, clip_path, output_path;  // as the user typed them; name files in messages
  std::vector<RawPolygon> subjects, clips;
  bool exact_output = false;  // --exact: also write outer_exact / holes_exact
  std::ostream* summary = nullptr;  // the short human summary (stdout)
};

// Return the exit code; throw UserError for bad input and unwritable output.
int run_clip_exact(const ClipJob& job);
int run_clip_epick(const ClipJob& job);
int run_clip_double(const ClipJob& job);

}  // namespace hlr::app
