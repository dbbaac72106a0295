// Frequency analysis of a clip (thesis chapter 4 "frequency analysis"): how much of each
// joint's motion lies in each Laplacian band of the multiresolution pyramid.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "processing/core/status.h"
#include "processing/filtering/pyramid.h"

namespace mocapfill {

// Energy of band k of a group of channels: mean over frames of the squared norm of the
// band's value over the group's columns, e.g. rad^2 for one joint's three tangent columns.
// Returns a (groups x bands) matrix; column `levels` (the last) is the residual G_fb's
// energy about its mean over time, so a constant pose contributes nothing.
// `column_groups[g]` lists the columns of group g (e.g. {3j, 3j+1, 3j+2} for joint j).
Eigen::MatrixXd BandEnergies(const Pyramid& pyramid, const std::vector<std::vector<int>>& column_groups);

// Share of each band in a group's total (rows sum to 1; all zero for a still group).
Eigen::MatrixXd BandEnergyShares(const Eigen::MatrixXd& energies);

}  // namespace mocapfill
