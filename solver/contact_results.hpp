#pragma once
/// Contact output values of one converged increment: one record per slave node per contact
/// pair, what field_output.* turns into CPRESS, COPEN, CSTATUS, CNAREA, CFN, CSHEAR1/2, CSLIP1/2
/// and CFS frames. Plain data.
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
  /// Frictional stress on the slave in the t1/t2 directions (contact/projection.hpp's basis): it
  /// opposes the slave's slip relative to the master, |CSHEAR| = μ CPRESS while slipping.
  /// Zero for frictionless pairs and open nodes.
  std::array<double, 2> cshear{0, 0};
  /// Accumulated relative tangential motion of the slave on the master in t1/t2 (elastic slip
  /// included), summed over increments while closed. Zero for frictionless pairs (not tracked).
  std::array<double, 2> cslip{0, 0};
  std::array<double, 3> cfs{0, 0, 0};  ///< frictional force on the slave node, A × (the stress above)
};

using ContactResults = std::vector<ContactNodeResult>;

}  // namespace inpact::solver
