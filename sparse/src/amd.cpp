// placeholder: replaced by the AMD implementation
#include "gab/sparse/amd.h"
namespace gab {
Status amd_order(const CscMatrix& lower, std::vector<int32_t>* perm, const AmdOptions&, AmdInfo*) {
  perm->resize(lower.ncols);
  for (int32_t i = 0; i < lower.ncols; ++i) (*perm)[i] = i;
  return Status::Ok();
}
}  // namespace gab
