// Fundamental supernodes and relaxed amalgamation.
#include "gab/sparse/supernodes.h"

#include <algorithm>

#include "gab/sparse/disjoint_set.h"

namespace gab {

std::vector<int32_t> fundamental_supernodes(const std::vector<int32_t>& parent,
                                            const std::vector<int32_t>& counts) {
  const int32_t n = static_cast<int32_t>(parent.size());
  std::vector<int32_t> nchildren(n, 0);
  for (int32_t j = 0; j < n; ++j) {
    if (parent[j] != -1) ++nchildren[parent[j]];
  }
  std::vector<int32_t> first;
  for (int32_t j = 0; j < n; ++j) {
    const bool joins_previous = j > 0 && parent[j - 1] == j && nchildren[j] == 1 &&
                                counts[j - 1] == counts[j] + 1;
    if (!joins_previous) first.push_back(j);
  }
  first.push_back(n);
  return first;
}

std::vector<int32_t> relax_supernodes(const std::vector<int32_t>& first_col,
                                      const std::vector<int32_t>& parent,
                                      const std::vector<int32_t>& counts,
                                      const RelaxOptions& options) {
  const int32_t ns = static_cast<int32_t>(first_col.size()) - 1;
  const int32_t n = first_col[ns];
  std::vector<int32_t> super_of(n);
  for (int32_t s = 0; s < ns; ++s) {
    for (int32_t j = first_col[s]; j < first_col[s + 1]; ++j) super_of[j] = s;
  }
  // Per group (keyed by its leader, the group's first fundamental supernode):
  // columns, rows counted from its first column, explicit zeros so far.
  std::vector<int64_t> cols(ns), rows(ns), zeros(ns, 0);
  std::vector<int32_t> link(ns);
  for (int32_t s = 0; s < ns; ++s) {
    link[s] = s;
    cols[s] = first_col[s + 1] - first_col[s];
    rows[s] = counts[first_col[s]];
  }
  // Visit from the top down, so a group that grows by absorbing its last
  // child can go on absorbing that child's last child.
  for (int32_t s = ns - 2; s >= 0; --s) {
    const int32_t last = first_col[s + 1] - 1;
    if (parent[last] == -1) continue;
    const int32_t g = find_set_root(&link, super_of[parent[last]]);
    if (g != s + 1) continue;  // not contiguous: s is not its parent's last child
    const int64_t k = cols[s] + cols[g];
    const int64_t m = cols[s] + rows[g];
    const int64_t z = zeros[s] + zeros[g] + cols[s] * (cols[s] + rows[g] - rows[s]);
    const double total = static_cast<double>(k * m - k * (k - 1) / 2);
    const double frac = static_cast<double>(z) / total;
    const bool merge = k <= options.cols[0] || (k <= options.cols[1] && frac < options.zeros[0]) ||
                       (k <= options.cols[2] && frac < options.zeros[1]) ||
                       frac < options.zeros[2];
    if (!merge) continue;
    link[g] = s;
    cols[s] = k;
    rows[s] = m;
    zeros[s] = z;
  }
  std::vector<int32_t> merged;
  for (int32_t s = 0; s < ns; ++s) {
    if (find_set_root(&link, s) == s) merged.push_back(first_col[s]);
  }
  merged.push_back(n);
  return merged;
}

// AnalyzeOptions' panel defaults (64 columns, at most 4 panels), measured
// at a 2.4M-vertex mesh: 3.94 -> 3.72 GB of factor with 4 panels, 3.69 GB
// with 8, whose extra passes over large update matrices made the
// factorization ~15% slower; 4 was as fast as no chains.
std::vector<int32_t> split_wide_supernodes(const std::vector<int32_t>& first_col, int32_t panel_cols,
                                           int32_t max_panels, std::vector<uint8_t>* continued) {
  std::vector<int32_t> cut;
  if (continued != nullptr) continued->clear();
  const size_t ns = first_col.empty() ? 0 : first_col.size() - 1;
  for (size_t s = 0; s < ns; ++s) {
    const int32_t k = first_col[s + 1] - first_col[s];
    int32_t panels = 1;
    if (panel_cols > 0 && k > panel_cols) {
      panels = std::min<int32_t>((k + panel_cols - 1) / panel_cols, std::max<int32_t>(max_panels, 1));
    }
    // Widths k / panels, the first k % panels of them one wider.
    for (int32_t q = 0, col = first_col[s]; q < panels; ++q) {
      cut.push_back(col);
      col += k / panels + (q < k % panels ? 1 : 0);
      if (continued != nullptr) continued->push_back(q + 1 < panels ? 1 : 0);
    }
  }
  cut.push_back(ns == 0 ? (first_col.empty() ? 0 : first_col[0]) : first_col[ns]);
  return cut;
}

}  // namespace gab
