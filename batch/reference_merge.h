// `prism merge`: the parts of a split reference render (reference_part.h) put together into the
// image one process renders with the same seed. The parts must be of one render (scene hash,
// size, paths per pixel, seed, settings, observer, exposure) and cover every pixel's every path
// index exactly once; anything else is refused with one line naming the first difference, gap
// or overlap. The result depends on the set of parts alone, not on their order, and parts are
// only read: merging again gives the same image.
//
// Exactness. A pixel covered by one part (a split by rows) is that part's float mean and
// variance, which are the whole render's bit for bit. A pixel covered by several (a split by path
// indices) combines them in path order by Chan, Golub & LeVeque 1979 ("Updating formulae and a
// pairwise algorithm for computing sample variances"): n = na + nb, δ = mb − ma,
// m = ma + δ·nb/n, M2 = M2a + M2b + δ²·na·nb/n, with each part's mean read as float mean + float
// residual (about 48 bits) and M2 = variance of the mean · n · (n − 1); the mean then agrees with
// the whole render's to double rounding before it is rounded to float.
#pragma once

#include <filesystem>
#include <vector>

#include "batch/reference_part.h"

namespace prism::batch {

// Error "merge: …" unless the parts are of one render and cover it exactly once, e.g.
// "merge: samples 32:48 of rows 90–134 are missing" or "merge: samples 0:16 of rows 0–44 are in
// both a.exr and b.exr" (rows inclusive, samples as --samples takes them).
void checkParts(const std::vector<std::filesystem::path>& files, const std::vector<ReferencePartHeader>& headers);

struct MergedReference {
  ReferencePartHeader header;  // the render's: the whole image and every path
  reference::ReferenceImage image;
};

// Reads the headers, checks them (checkParts), then reads and adds the parts one at a time.
MergedReference mergeReferenceParts(const std::vector<std::filesystem::path>& files);

}  // namespace prism::batch
