#pragma once
/// Contact output values of one converged increment: one record per slave node per contact
/// pair, what field_output.* turns into CPRESS, COPEN, CSTATUS, CNAREA and CFN frames. Plain data.
#include <array>
#include <cstdint>
#include <vector>

namespace inpact::solver {

/// CSTATUS coding, after Abaqus/CAE's contact status categories Open, Closed (Sticking) and
/// Closed (Slipping) (Abaqus/CAE User's Guide, "Selecting contact output"); a frictionless
/// closed node is slipping, as Abaqus reports it.
enum class ContactStatus : std::uint8_t { Open = 0, Sticking = 1, Slipping = 2 };

struct ContactNodeResult {
  std::int32_t pair = 0;  ///< row of the contact pair table (model pairs, then each step's)
  std::int64_t node = 0;  ///< slave node row
  double cpress = 0.0;    ///< contact pressure
  double copen = 0.0;     ///< gap (positive open, negative penetration); NaN with no master in range
  ContactStatus cstatus = ContactStatus::Open;
  double cnarea = 0.0;    ///< the node's contact area when closed, else 0
  std::array<double, 3> cfn{0, 0, 0};  ///< normal contact force on the slave node, p A n
};

using ContactResults = std::vector<ContactNodeResult>;

}  // namespace inpact::solver
