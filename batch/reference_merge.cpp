#include "batch/reference_merge.h"

#include <algorithm>
#include <numeric>
#include <optional>
#include <set>

#include <fmt/format.h>

#include "core/error.h"

namespace prism::batch {
namespace {

// What is wrong with one band of rows: path indices [sampleBegin, sampleEnd) missing (no parts)
// or covered by both parts `first` and `second`.
struct Problem {
  int sampleBegin = 0, sampleEnd = 0;
  std::optional<std::size_t> first, second;
  bool operator==(const Problem&) const = default;
};

// The first gap or overlap of the band [rowBegin, rowEnd), which every part either covers or
// misses whole.
std::optional<Problem> bandProblem(const std::vector<ReferencePartHeader>& headers, int rowBegin, int rowEnd) {
  std::vector<std::size_t> covering;
  for (std::size_t i = 0; i < headers.size(); ++i) {
    if (headers[i].region.rowBegin <= rowBegin && headers[i].region.rowEnd >= rowEnd) covering.push_back(i);
  }
  std::sort(covering.begin(), covering.end(), [&](std::size_t a, std::size_t b) {
    return std::pair(headers[a].region.sampleBegin, headers[a].region.sampleEnd) <
           std::pair(headers[b].region.sampleBegin, headers[b].region.sampleEnd);
  });
  int covered = 0;  // [0, covered) is covered, last by part `last`
  std::size_t last = 0;
  for (std::size_t i : covering) {
    const reference::ReferenceRegion& r = headers[i].region;
    if (r.sampleBegin > covered) return Problem{covered, r.sampleBegin, {}, {}};
    if (r.sampleBegin < covered) return Problem{r.sampleBegin, std::min(covered, r.sampleEnd), last, i};
    covered = r.sampleEnd;
    last = i;
  }
  const int total = headers.front().samplesPerPixel;
  if (covered < total) return Problem{covered, total, {}, {}};
  return std::nullopt;
}

}  // namespace

void checkParts(const std::vector<std::filesystem::path>& files, const std::vector<ReferencePartHeader>& headers) {
  PRISM_CHECK(files.size() == headers.size());
  if (files.empty()) throw Error("merge: no parts given");
  const auto identity = headers.front().identity();
  for (std::size_t i = 1; i < headers.size(); ++i) {
    const auto other = headers[i].identity();
    for (std::size_t k = 0; k < identity.size(); ++k) {
      if (other[k].second != identity[k].second) {
        throw Error(fmt::format("merge: {} is a part of another render: its {}: \"{}\"; {}'s: \"{}\"",
                                files[i].string(), identity[k].first, excerpt(other[k].second),
                                files.front().string(), excerpt(identity[k].second)));
      }
    }
    // Decided by the scene and the camera, so equal in parts of one render (but for another
    // build's fit, or an edited file).
    if (headers[i].cameraToXyz != headers.front().cameraToXyz)
      throw Error(fmt::format("merge: {}: its camera matrix is not {}'s (the parts of one render share it)",
                              files[i].string(), files.front().string()));
  }
  std::set<int> bounds{0, headers.front().height};
  for (const ReferencePartHeader& h : headers) bounds.insert({h.region.rowBegin, h.region.rowEnd});
  const std::vector<int> rows(bounds.begin(), bounds.end());
  for (std::size_t b = 0; b + 1 < rows.size(); ++b) {
    std::optional<Problem> problem = bandProblem(headers, rows[b], rows[b + 1]);
    if (!problem) continue;
    std::size_t end = b + 1;  // the rows with the same problem, for one message
    while (end + 1 < rows.size() && bandProblem(headers, rows[end], rows[end + 1]) == problem) ++end;
    const std::string where = fmt::format("samples {}:{} of rows {}–{}", problem->sampleBegin, problem->sampleEnd,
                                          rows[b], rows[end] - 1);
    if (!problem->first) throw Error(fmt::format("merge: {} are missing", where));
    throw Error(fmt::format("merge: {} are in both {} and {}", where, files[*problem->first].string(),
                            files[*problem->second].string()));
  }
}

MergedReference mergeReferenceParts(const std::vector<std::filesystem::path>& files) {
  std::vector<ReferencePartHeader> headers;
  for (const std::filesystem::path& f : files) headers.push_back(readReferencePartHeader(f));
  checkParts(files, headers);

  // In path order for every row (rows are covered by parts in order of their first path index):
  // the result depends on the set of parts, not on the order they were given in.
  std::vector<std::size_t> order(files.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::pair(headers[a].region.sampleBegin, headers[a].region.rowBegin) <
           std::pair(headers[b].region.sampleBegin, headers[b].region.rowBegin);
  });
  MergedReference merged{headers.front(), {}};
  const int width = merged.header.width, height = merged.header.height;
  merged.header.region = {0, height, 0, merged.header.samplesPerPixel};
  reference::ReferenceImage& out = merged.image;
  out = {imaging::FloatImage(width, height, 3), imaging::FloatImage(width, height, 3),
         imaging::FloatImage(width, height, 3)};
  const std::size_t values = out.tristimulus.pixels.size();
  std::vector<double> mean(values, 0.0), m2(values, 0.0);  // Chan's running mean and M2
  std::vector<int> count(static_cast<std::size_t>(height), 0), parts(static_cast<std::size_t>(height), 0);  // per row

  for (std::size_t index : order) {
    ReferencePart part = readReferencePart(files[index]);
    if (!(part.header == headers[index])) throw Error(fmt::format("merge: {} changed while it was read", files[index].string()));
    const reference::ReferenceRegion& r = part.header.region;
    const double nb = r.samples();
    for (int y = r.rowBegin; y < r.rowEnd; ++y) {
      const double na = count[static_cast<std::size_t>(y)], n = na + nb;
      const std::size_t rowStart = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) * 3;
      const std::size_t partStart = static_cast<std::size_t>(y - r.rowBegin) * static_cast<std::size_t>(width) * 3;
      for (std::size_t k = 0; k < static_cast<std::size_t>(width) * 3; ++k) {
        const float hi = part.image.tristimulus.pixels[partStart + k];
        const float variance = part.image.variance.pixels[partStart + k];
        const double mb = double{hi} + double{part.image.meanResidual.pixels[partStart + k]};
        const double m2b = double{variance} * nb * (nb - 1.0);
        const std::size_t g = rowStart + k;
        if (parts[static_cast<std::size_t>(y)] == 0) {
          mean[g] = mb;
          m2[g] = m2b;
          out.tristimulus.pixels[g] = hi;  // a pixel of one part is that part's, bit for bit
          out.variance.pixels[g] = variance;
        } else {
          const double delta = mb - mean[g];
          mean[g] += delta * nb / n;
          m2[g] += m2b + delta * delta * na * nb / n;
        }
      }
      count[static_cast<std::size_t>(y)] += r.samples();
      ++parts[static_cast<std::size_t>(y)];
    }
  }
  for (int y = 0; y < height; ++y) {
    const double n = count[static_cast<std::size_t>(y)];
    for (std::size_t k = 0; k < static_cast<std::size_t>(width) * 3; ++k) {
      const std::size_t g = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) * 3 + k;
      if (parts[static_cast<std::size_t>(y)] > 1) {
        out.tristimulus.pixels[g] = static_cast<float>(mean[g]);
        out.variance.pixels[g] = n > 1.0 ? static_cast<float>(m2[g] / (n - 1.0) / n) : 0.0f;
      }
      out.meanResidual.pixels[g] = static_cast<float>(mean[g] - double{out.tristimulus.pixels[g]});
    }
  }
  return merged;
}

}  // namespace prism::batch
