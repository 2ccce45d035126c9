#include "pipeline/anchor_layouts.h"

#include <algorithm>

#include "anchors/anchor_chunk.h"
#include "anchors/anchor_levels.h"
#include "reconstruction/shape_operator.h"

namespace gab {

ChunkLayout encode_selection_layout(const AnchorSchedule& schedule, const GridPositions& grid) {
  ChunkLayout out;
  AnchorModels models;
  AnchorChunkCoder coder(grid.quantizer, &models);
  std::vector<char> coded(grid.index.size() / 3, 0);  // anchored by the chunks written so far
  int32_t begin = 0;
  for (size_t k = 0; k < schedule.cuts.size(); ++k) {
    std::vector<int32_t> anchors(schedule.order.begin() + begin, schedule.order.begin() + schedule.cuts[k]);
    std::sort(anchors.begin(), anchors.end());
    const double* prediction = k == 0 ? nullptr : schedule.shapes[k - 1].data();
    out.add(coder.encode(anchors, coded, grid.index, prediction), anchors);
    for (int32_t v : anchors) coded[v] = 1;
    begin = schedule.cuts[k];
  }
  return out;
}

Status encode_level_layout(const AnchorSchedule& schedule, const EdgeGraph& graph, double weight, double growth,
                           int32_t threads, const OrderingPlan& ordering, uint8_t reconstruction,
                           const IterativeTuning& tuning, const GridPositions& grid, ChunkLayout* out) {
  std::vector<int32_t> spread(schedule.order.begin(), schedule.order.begin() + schedule.spread);
  std::vector<int32_t> rest(schedule.order.begin() + schedule.spread, schedule.order.end());
  std::sort(spread.begin(), spread.end());
  std::sort(rest.begin(), rest.end());
  LevelPlan plan;
  plan.spread = schedule.spread;
  plan.rest = static_cast<int32_t>(rest.size());
  plan.growth16 = level_growth16(growth);
  const std::vector<int32_t> sizes = plan.level_sizes();
  std::vector<int32_t> order;
  GAB_RETURN_IF_ERROR(level_order(graph, spread, rest, plan.rest - (sizes.empty() ? 0 : sizes.back()), &order));
  AnchorModels models;
  AnchorChunkCoder coder(grid.quantizer, &models);
  out->add(coder.encode_level_head(plan, spread, rest, grid.index), spread);

  LevelMembers members(order, rest, graph.num_vertices());
  // The decoder's shapes: the global operator's from level 2 on (level 1's
  // prediction is the spread set's, the schedule's first shape: one
  // factorization saved); the iterative operator's from the spread set on.
  ShapeOperator levels(reconstruction);
  GAB_RETURN_IF_ERROR(tune(tuning, &levels));
  levels.set_threads(threads);
  levels.apply(ordering);
  const bool from_spread = !levels.global();
  std::vector<double> shape;
  std::vector<int32_t> before = spread, previous;  // before level 2: the spread set and level 1
  if (from_spread) GAB_RETURN_IF_ERROR(levels.init(graph, weight, spread, grid.coefficients_of(spread)));
  for (size_t k = 0; k < sizes.size(); ++k) {
    std::vector<int32_t> level = members.next(sizes, k);
    if (k == 1 && !from_spread) {
      before.insert(before.end(), previous.begin(), previous.end());
      GAB_RETURN_IF_ERROR(levels.init(graph, weight, before, grid.coefficients_of(before)));
    } else if (k > 0) {
      GAB_RETURN_IF_ERROR(levels.add_anchors(previous, grid.coefficients_of(previous)));
    }
    if (k > 0 || from_spread) GAB_RETURN_IF_ERROR(levels.prediction(&level, &shape));
    const double* prediction = k == 0 && !from_spread ? schedule.shapes[0].data() : shape.data();
    out->add(coder.encode_level(level, grid.index, prediction, graph), level);
    previous = std::move(level);
  }
  return Status::Ok();
}

}  // namespace gab
