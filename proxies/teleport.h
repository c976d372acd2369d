#pragma once
// VSSA's teleport over a whole character's sphere sets (Wang et al. 2006; notes/sh-math.md §6):
// move a sphere from where it is redundant to where the spheres bulge most out of the mesh,
// keeping the sphere count. Everything is in bind space, meters.
//
//   TeleportJob job;
//   job.sets = sets;                 // one BoneSphereSet per bone, edited in place
//   job.tolerance = tau;             // protrusion every set must keep (or the worst before)
//   TeleportStats stats;
//   job.stats = &stats;
//   if (Status s = job.run(); !s) return s;
//
// One move: among the `candidates` splittable spheres with the largest outside volume (over all
// sets), each is split in two (its bone re-clustered); then, over every set of two or more spheres
// (the split set as split), the sphere whose removal (its bone re-clustered) raises the summed
// outside volume least is dropped. Moves that would let any protrusion exceed
// max(tolerance, the worst protrusion before the teleport) are not considered. The move with
// the lowest net change of the summed outside volume is made. A move that does not lower it is
// "worsening": up to `worsening` of them in a row are made (VSSA accepts a few worsening
// mutations to leave a local minimum); the job ends after `rounds` moves, after that many
// worsening ones in a row, or when no move exists, and leaves the sets in the state with the
// lowest summed outside volume it has seen. Deterministic: ties go to the lower set and sphere
// index.
#include <memory>
#include <span>

#include "base/result.h"
#include "proxies/sphere_set_fit.h"

namespace proxygi::proxies {

struct TeleportStats {
  int moves = 0;            // moves made (worsening ones included)
  int kept = 0;             // moves in the state left behind
  float outside_before = 0.0f;  // summed outside volume of every sphere, m³ (fit estimate)
  float outside_after = 0.0f;
};

struct TeleportJob {
  // Input and output: the sets, edited in place (non-null entries).
  std::span<std::unique_ptr<BoneSphereSet>> sets;
  // Inputs.
  float tolerance = 0.0f;   // meters (> 0)
  int rounds = 64;          // cap on moves (>= 0; 0 does nothing)
  int candidates = 1;       // splits tried per move (>= 1)
  int worsening = 0;        // worsening moves allowed in a row (>= 0)
  int lloyd_iterations = 6; // re-clustering passes after a split or removal (>= 1)
  // Output (optional).
  TeleportStats* stats = nullptr;

  Status validate() const;
  // validate(), then teleport.
  Status run() const;
};

}  // namespace proxygi::proxies
