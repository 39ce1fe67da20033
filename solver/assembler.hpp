#pragma once
/// Assembly of the element contributions: the reduced tangent K_r = Tᵀ K T into a pattern built
/// once per DOF map, and the full internal force vector f_int(u) (reactions are read from it).
#include <array>
#include <span>
#include <string>
#include <vector>

#include "analysis_model.hpp"
#include "dof_map.hpp"
#include "element_activity.hpp"
#include "elements/element_kernel.hpp"
#include "iteration_seconds.hpp"
#include "linear/petsc_module.hpp"
#include "linear/sparse_matrix.hpp"

namespace inpact::solver {

class MaterialStates;

struct AssemblyRequest {
  bool tangent = true;
  bool nlgeom = false;
  std::span<const double> delta_t;  ///< nodal temperature change, or empty
  /// Keep every element's integration-point results (stress, strain) at u: the output of a
  /// converged increment then reads them instead of computing the elements again.
  bool points = false;
  /// With the tangent: also the product K·v of the element stiffnesses with the full DOF vector
  /// `multiply`, over every DOF (prescribed ones too), added into `product` (full size).
  std::span<const double> multiply = {};
  std::span<double> product = {};
};

/// Integration-point results of every element, in element order.
struct ElementPoints {
  std::vector<std::size_t> offset;  ///< element e: points[offset[e], offset[e + 1])
  std::vector<elements::PointResult> points;
  std::span<const elements::PointResult> of(std::size_t e) const {
    return std::span(points).subspan(offset[e], offset[e + 1] - offset[e]);
  }
};

/// Couplings beyond the elements' (contact): blocks of global DOFs that couple with each other
/// (a slave node and its master facet's nodes), and Lagrange multipliers, each an equation
/// appended after the DOF map's that couples with a block of global DOFs.
struct ExtraCouplings {
  std::vector<std::vector<std::int64_t>> dof_blocks;
  std::vector<std::vector<std::int64_t>> multiplier_dofs;  ///< multiplier m: equation n_eq + m
};

/// The smallest value of a per-element measure and the lowest element row that has it.
struct SmallestAtElement {
  double value = 0.0;
  std::int64_t element = -1;  ///< none yet
  void offer(double v, std::int64_t e) {
    if (element < 0 || v < value) {
      value = v;
      element = e;
    }
  }
};

struct AssemblyResult {
  /// Per field (fields.hpp), the spatial average of the magnitudes of the element nodal forces
  /// (moments in the rotation field), Abaqus's q^α "typical flux" that residuals are measured
  /// against.
  PerField average_force{};
  std::array<std::size_t, kFields> n_force_entries{};  ///< how many element nodal forces each average is over
  /// With AssemblyRequest::multiply: the same averages for the element forces f_e + k_e·v (the
  /// linearised state moved by v), which the increment measures its residuals against.
  PerField moved_average_force{};
  /// Smallest Jacobian determinant of the reference geometry at an integration point.
  SmallestAtElement jacobian;
  /// NLGEOM: smallest det F at an integration point (elements::ElementSystem::min_volume_ratio).
  SmallestAtElement volume_ratio;
};

/// One line on how a distributed run shares its work (for the log and the .sta); "" on one rank.
std::string describe_distribution(const AnalysisModel& am, RankWorld world);

/// On the ranks of a distributed run (mpirun, linear/petsc_module.hpp RankWorld) each rank
/// evaluates its share of the elements (element_partition.hpp): the internal forces are
/// summed over the ranks (every rank has f_int whole), the tangent is not: each rank's pattern
/// and values hold its elements' part (add_diagonal: the diagonal of its nodes' equations,
/// ElementPartition::rank_of_node), which the PETSc solver adds up. The terms beyond the
/// elements (contact: set_extra_couplings, add_local_matrix and the other add_ functions) are
/// added by every rank as it gives them: their caller shares them out (contact: each slave node
/// on the rank of its rows). An assembly that keeps points evaluates every element on every rank
/// (complete_states).
class Assembler {
 public:
  /// `threads`: element computations run on this many threads (the sum stays in element order).
  /// `states`: the points' material history (material_states.hpp); every assembly evaluates
  /// from its committed state and writes its trial state. Null: no element has state.
  Assembler(const AnalysisModel& am, const DofMap& dofs, int threads = 1, MaterialStates* states = nullptr);

  /// The reduced tangent's pattern (upper triangle); assemble() fills its values (on a
  /// distributed run this rank's part of both).
  SparseMatrix& tangent() { return tangent_; }
  const DofMap& dofs() const { return dofs_; }
  /// Size of the system: the DOF map's equations plus the multipliers of set_extra_couplings().
  std::int64_t n_equations() const { return tangent_.n; }
  /// Makes the pattern the elements' couplings and `extra`'s (contact, whenever its couplings or
  /// multipliers change), and zeroes its values. The pattern is rebuilt (the linear solvers
  /// redo their analysis then) unless it is that already. On a distributed run `extra` holds
  /// this rank's couplings, and every multiplier of the system (those another rank couples with
  /// an empty block).
  void set_extra_couplings(const ExtraCouplings& extra);

  /// Internal forces at u (full, overwritten) and, when asked, the reduced tangent.
  AssemblyResult assemble(std::span<const double> u, const AssemblyRequest& request, std::span<double> f_int);

  /// Whether the ranks share the elements (a distributed run).
  bool distributed() const { return world_.distributed(); }
  /// A distributed run at a converged state: every element evaluated once at u on every rank,
  /// its points kept (request's NLGEOM and temperature), so that each rank has the trial material
  /// state of every element to commit and the output its points. Nothing on one rank.
  void complete_states(std::span<const double> u, const AssemblyRequest& request);

  /// Reduces a full vector to the equations: r_eq = Σ_d w_d r_d over the DOFs feeding each one.
  void reduce(std::span<const double> full, std::span<double> reduced) const;

  /// Adds a local matrix k (n × n, row-major) on global DOFs `dofs` into the reduced tangent,
  /// through the DOF map's masters, as the elements' are (contact blocks: their couplings must
  /// be in the pattern, set_extra_couplings).
  void add_local_matrix(std::span<const std::int64_t> dofs, std::span<const double> k) { scatter(dofs, k); }

  /// Adds `value` to the diagonal of free DOF `dof` (nothing for another kind): on a distributed
  /// run on the rank of its node, so that each rank adds its own.
  void add_diagonal(std::int64_t dof, double value);

  /// The equations each local unknown feeds, with their weights (the DOF map's masters of a
  /// DOF, or a multiplier's own equation).
  using LocalEquations = std::vector<std::vector<std::pair<std::int64_t, double>>>;
  /// One entry of the skew part ½(K − Kᵀ) of an unsymmetric tangent, kept beside the matrix.
  struct SkewEntry {
    std::int64_t row, col;
    double value;
  };
  /// Adds a local matrix k (n × n, row-major, n = eqs.size()) that need not be symmetric: its
  /// symmetric part ½(k + kᵀ) into the tangent's upper triangle, its skew part (when not zero)
  /// to `skew` (friction: Newton then solves with the full matrix).
  void add_unsymmetric_matrix(const LocalEquations& eqs, std::span<const double> k, std::vector<SkewEntry>& skew);
  /// Adds the column scale · gradient (on global DOFs `dofs`, through their masters) at the
  /// multiplier equation `row` (above the diagonal: DOF equations come first), and `diagonal`
  /// to its diagonal.
  void add_multiplier_column(std::int64_t row, std::span<const std::int64_t> dofs, double scale,
                             std::span<const double> gradient, double diagonal);

  /// The point results kept by the last assembly that asked for them (AssemblyRequest::points),
  /// when it was made at exactly this u, temperature change and NLGEOM; otherwise null.
  const ElementPoints* points_at(std::span<const double> u, std::span<const double> delta_t, bool nlgeom) const;

  /// *MODEL CHANGE: the step's active elements (inactive ones add no force and no stiffness;
  /// their points, kept for output, are at zero strain) and the reference displacements of the
  /// elements reactivated strain free. Both must outlive the assembler's use.
  void set_elements(const StepElements* elements, const ElementReferences* references) {
    elements_ = elements;
    references_ = references;
  }
  /// The internal forces (full vector) of elements `rows` alone at u: what a removal releases.
  std::vector<double> element_forces(std::span<const std::int32_t> rows, std::span<const double> u,
                                     const AssemblyRequest& request);

  /// Wall time in assemble() so far (element_assembly and its count only).
  const IterationSeconds& seconds() const { return seconds_; }

 private:
  /// Global DOFs of element e, node-major.
  void element_dofs(std::size_t e, std::vector<std::int64_t>& dofs) const;
  /// Whether this rank evaluates element e for the tangent (every element on one rank).
  bool owns(std::size_t e) const { return !world_.distributed() || rank_of_element_[e] == world_.rank; }
  /// Whether this rank adds the diagonal terms of node `node`'s equations (rank_of_node).
  bool owns_node(std::int64_t node) const {
    return !world_.distributed() || rank_of_node_[static_cast<std::size_t>(node)] == world_.rank;
  }
  /// The smallest value over the ranks, and the lowest element row that has it.
  void smallest_over_ranks(SmallestAtElement& smallest) const;
  /// Sums a partitioned assembly's forces and force measures over the ranks.
  /// Per field: Σ|f_e|, Σ|f_e + k_e·v| and how many entries (AssemblyResult's averages).
  struct FieldSums {
    PerField force{}, moved{}, count{};
  };
  void sum_over_ranks(const AssemblyRequest& request, std::span<double> f_int, FieldSums& sums,
                      AssemblyResult& result) const;
  /// The elements' pattern (every diagonal in it), all of it flagged in element_entry_.
  void build_element_pattern();
  /// Adds to `pattern` the couplings of global DOFs `block` through their masters; with a
  /// `multiplier_eq` (>= 0) those of the multiplier with them instead. `eqs`: scratch.
  void add_couplings(PatternBuilder& pattern, std::span<const std::int64_t> block, std::int64_t multiplier_eq,
                     std::vector<std::int64_t>& eqs) const;

  /// Element e's system into `out` (its buffers are reused from element to element).
  void compute(std::size_t e, std::span<const double> u, const AssemblyRequest& request,
               elements::ElementSystem& out) const;
  /// Adds element matrix k (n × n, row-major) on DOFs `el_dofs` into the reduced tangent.
  void scatter(std::span<const std::int64_t> el_dofs, std::span<const double> k);
  /// add_unsymmetric_matrix() where each unknown feeds one equation of its own with weight 1,
  /// by scatter()'s column walk; false, with nothing added, otherwise.
  bool add_unsymmetric_plain(const LocalEquations& eqs, std::span<const double> k, std::vector<SkewEntry>& skew);
  /// The pattern is the elements' and exactly `extra`'s couplings already.
  bool has_exactly(const ExtraCouplings& extra) const;
  /// The equations the global DOFs `block` feed through their masters, into `eqs`.
  void block_equations(std::span<const std::int64_t> block, std::vector<std::int64_t>& eqs) const;
  /// Local blocks up to this many DOFs take scatter()'s sorted column walk (a 27-node brick has
  /// 81; a smoothed contact node's block, its facets' and its master points' nodes, a few hundred).
  static constexpr std::size_t kMaxLocal = 384;
  /// request.product += k · request.multiply on the element's DOFs; adds Σ |f + k · v| over
  /// them (f the element's forces) to `moved`, per field.
  void multiply(std::span<const std::int64_t> el_dofs, const elements::ElementSystem& sys,
                const AssemblyRequest& request, PerField& moved) const;

  const AnalysisModel& am_;
  const DofMap& dofs_;
  SparseMatrix tangent_;
  /// Per entry of tangent_: whether an element block couples it. The elements' couplings do not
  /// change in the assembler's life, so set_extra_couplings() builds only the extra ones (contact
  /// changes them from one iteration to the next) and merges them with these, one bit per entry.
  std::vector<bool> element_entry_;
  int threads_ = 1;
  MaterialStates* states_ = nullptr;
  RankWorld world_;
  std::vector<int> rank_of_element_;        ///< a distributed run's partition (else empty)
  std::vector<std::size_t> own_elements_;   ///< the elements this rank evaluates, ascending
  std::vector<int> rank_of_node_;           ///< a distributed run's rank_of_node (else empty)
  ElementPoints points_;
  std::vector<double> points_u_, points_delta_t_;  ///< the state points_ were computed at
  bool points_nlgeom_ = false, have_points_ = false;
  IterationSeconds seconds_;
  const StepElements* elements_ = nullptr;
  const ElementReferences* references_ = nullptr;
};

}  // namespace inpact::solver
