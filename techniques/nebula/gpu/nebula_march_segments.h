// How the GPU march is split into dispatches so that no shader invocation runs more loop
// iterations than its driver allows. Mesa's llvmpipe (CI's GPU, and any machine without one)
// stops every loop of an invocation once all its loops together have iterated 65 535 times
// (LP_MAX_TGSI_LOOP_ITERATIONS) and goes on with whatever the loops had summed: a march of many
// stars or many steps then loses light without an error (measured: one Wien star under CIE 1931
// kept all its light up to 607 steps, eight up to 81; the reference at the paper's settings with
// eight stars up to 146). Split into ranges of steps and of items (the stars of the direct methods,
// the groups of lanes of projection and light–density), each dispatch carries on from where the
// last left the pixel (nebula_march.comp's uStepBegin…uItemEnd), so that every dispatch stays
// within the budget by an upper bound of its loop iterations.
#pragma once

#include <vector>

namespace prism::nebula {

// An upper bound of one invocation's loop iterations (back edges), in three parts. Only loops of
// constant count without loops inside are taken as unrolled (nebula_march.comp's chunks are
// written so that they are); every other loop counts each of its iterations.
struct MarchLoopCost {
  long fixed = 0;    // per invocation: clearing and writing the pixel's values, the group loop
  long perStep = 0;  // per step (per step and group where itemsMarchSteps): the step loop, the lines
  long perItem = 0;  // per step and item: a star's nodes or pieces, a group's lanes
  // Projection and light–density march the steps once per group (the steps' loop inside the
  // items'); the direct methods loop over their stars inside each step.
  bool itemsMarchSteps = false;
};

// One dispatch: steps [stepBegin, stepEnd) of items [itemBegin, itemEnd).
struct MarchSegment {
  int stepBegin = 0, stepEnd = 0, itemBegin = 0, itemEnd = 0;
};

// The bound of one dispatch of `steps` steps and `items` items.
long marchLoopIterations(const MarchLoopCost& cost, int steps, int items);

// Dispatches covering every step of every item once, steps in order (each range of steps takes
// all items before the next begins), each within `budget` loop iterations; one when it all fits.
// items 0 (a march without stars) still marches its steps, as one item range [0, 0). Error when a
// single step of a single item exceeds the budget.
std::vector<MarchSegment> planMarchSegments(const MarchLoopCost& cost, int steps, int items, long budget);

}  // namespace prism::nebula
