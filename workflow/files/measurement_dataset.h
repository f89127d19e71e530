#pragma once
// Reading one measured value from a dataset table (datasets/<source>/<name>.csv: a header line,
// comma-separated fields, double quotes around fields with commas). A row is picked by its
// `material` and `coating_PEG_wt_pct`; the value and standard-deviation columns are named by
// the observable ("angle_deg" and "angle_sd_deg"). The row's `source` column is the
// measurement's provenance.
#include <string>

#include "calibrate/calibration.h"

namespace demcal::workflow {

struct DatasetQuery {
  std::string path;
  std::string material;
  double coating_PEG_wt_pct = 0;
  std::string value_column;  // e.g. "angle_deg"
  std::string sd_column;     // e.g. "angle_sd_deg"; an empty cell = not reported
};

// Fills value, source and (if the dataset has one) uncertainty; *has_sd says whether it did.
// False with a message naming the file, the row or the column otherwise.
bool ReadDatasetMeasurement(const DatasetQuery& query, calibrate::Measurement* out, bool* has_sd,
                            std::string* error);

}  // namespace demcal::workflow
