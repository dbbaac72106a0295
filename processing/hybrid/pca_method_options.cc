#include "processing/hybrid/pca_method_options.h"

#include <cmath>
#include <string>

namespace mocapfill {

namespace {

Status RangeError(const char* field, double value, const char* range) {
  return InvalidArgument(std::string(field) + ": " + std::to_string(value) + " is out of range " + range);
}

}  // namespace

Status PcaMethodOptions::Validate() const {
  RETURN_IF_ERROR(model.Validate().WithContext("model"));
  RETURN_IF_ERROR(closed_form.Validate().WithContext("closed_form"));
  RETURN_IF_ERROR(fit.Validate().WithContext("fit"));
  for (size_t i = 0; i < band_gains.size(); ++i)
    if (!(band_gains[i] >= 0.0 && band_gains[i] <= 10.0))
      return RangeError(("band_gains[" + std::to_string(i) + "]").c_str(), band_gains[i], "[0, 10]");
  for (const ComponentDial& d : dials)
    if (d.component < 0 || !std::isfinite(d.sigmas))
      return InvalidArgument("dials: component " + std::to_string(d.component) + " = " + std::to_string(d.sigmas) +
                             " is not a valid dial");
  return OkStatus();
}

}  // namespace mocapfill
