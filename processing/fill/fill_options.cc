#include "processing/fill/fill_options.h"

namespace mocapfill {

Status FillOptions::Validate() const {
  RETURN_IF_ERROR(FragmentFillOptions::Validate());
  return pca.Validate().WithContext("pca");
}

}  // namespace mocapfill
