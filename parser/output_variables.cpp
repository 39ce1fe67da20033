#include "output_variables.hpp"

#include <algorithm>
#include <cctype>
#include <span>

namespace inpact::parser {

namespace {

/// What may follow a variable's name to select one component.
enum class Components : std::uint8_t {
  None,    ///< a scalar (MISES, CPRESS) or a name that already is a component (CSHEAR1)
  Vector,  ///< 1..3 (U1, RF2, SP3 for principal values)
  Tensor,  ///< 11, 22, 33, 12, 13, 23 (S11, E23)
  Index    ///< any positive number (SDV1, SDV12: solution-dependent state variables)
};

struct Variable {
  std::string_view name;
  Components components;
};

using C = Components;

// Nodal: displacements, rotations, velocities, accelerations, reactions, applied forces,
// coordinates, temperatures (Abaqus); PU, PNT ... are CalculiX *NODE FILE/*NODE PRINT keys
// (PU/PRF magnitude and phase of U/RF, PN/PS/PT/TS/TT/MF network and fluid quantities).
constexpr Variable kNode[] = {
    {"U", C::Vector},   {"UT", C::Vector},   {"UR", C::Vector},  {"V", C::Vector},    {"VT", C::Vector},
    {"VR", C::Vector},  {"A", C::Vector},    {"AT", C::Vector},  {"AR", C::Vector},   {"RF", C::Vector},
    {"RT", C::Vector},  {"RM", C::Vector},   {"CF", C::Vector},  {"CM", C::Vector},   {"TF", C::Vector},
    {"TM", C::Vector},  {"COORD", C::Vector}, {"NT", C::None},   {"RFL", C::None},    {"CFL", C::None},
    {"POR", C::None},   {"VF", C::Vector},   {"PU", C::None},    {"PRF", C::None},    {"PNT", C::None},
    {"PN", C::None},    {"PS", C::None},     {"PT", C::None},    {"TS", C::None},     {"TT", C::None},
    {"MF", C::None},    {"CP", C::None},     {"DEPT", C::None},  {"DEPF", C::None},   {"HCRI", C::None},
    {"SEN", C::None},   {"MAXU", C::None},   {"MACH", C::None},  {"TURB", C::None},   {"POT", C::None},
    {"PSF", C::None},   {"TSF", C::None},    {"PTF", C::None},   {"TTF", C::None}};

// Element: stresses and their invariants, strains (total, elastic, thermal, plastic, creep,
// logarithmic, nominal, rates), energies, volumes, state variables, temperature, heat flux,
// nodal forces, section forces and moments SF, SM (Abaqus); ME, ZZS, ERR, HER, MAXE, MAXS, SMID/SNEG/SPOS, SVF, PHS, EMFE/EMFB,
// ECD, HFLF, ELKE, EMAS, EBHE, CENT are CalculiX *EL FILE/*EL PRINT keys; NOE is CalculiX's
// "no error estimate" (it switches ZZS/ERR off and asks for nothing). DG (deformation gradient),
// FV (field variables), UVARM, SE and SK (section strains and curvatures) are Abaqus's too.
constexpr Variable kElement[] = {
    {"S", C::Tensor},     {"SP", C::Vector},    {"MISES", C::None},   {"TRESCA", C::None},  {"PRESS", C::None},
    {"INV3", C::None},    {"TRIAX", C::None},   {"E", C::Tensor},     {"EP", C::Vector},    {"EE", C::Tensor},
    {"EEP", C::Vector},   {"IE", C::Tensor},    {"THE", C::Tensor},   {"THEP", C::Vector},  {"PE", C::Tensor},
    {"PEP", C::Vector},   {"PEEQ", C::None},    {"PEEQT", C::None},   {"PEMAG", C::None},   {"CE", C::Tensor},
    {"CEEQ", C::None},    {"CEMAG", C::None},   {"LE", C::Tensor},    {"LEP", C::Vector},   {"NE", C::Tensor},
    {"NEP", C::Vector},   {"ER", C::Tensor},    {"ERP", C::Vector},   {"ME", C::Tensor},    {"ENER", C::None},
    {"ELEN", C::None},    {"SENER", C::None},   {"PENER", C::None},   {"CENER", C::None},   {"VENER", C::None},
    {"ELSE", C::None},    {"ELPD", C::None},    {"ELCD", C::None},    {"ELVD", C::None},    {"ELKE", C::None},
    {"ESEDEN", C::None},  {"EPDDEN", C::None},  {"EVOL", C::None},    {"IVOL", C::None},    {"SVOL", C::None},
    {"STH", C::None},     {"SF", C::Vector},    {"SM", C::Vector},    {"COORD", C::Vector}, {"SDV", C::Index},    {"STATUS", C::None},
    {"TEMP", C::None},    {"HFL", C::Vector},   {"HFLF", C::None},    {"NFORC", C::None},   {"ZZS", C::None},
    {"ERR", C::None},     {"HER", C::None},     {"MAXE", C::None},    {"MAXS", C::None},    {"SMID", C::None},
    {"SNEG", C::None},    {"SPOS", C::None},    {"SVF", C::None},     {"PHS", C::None},     {"EMFE", C::None},
    {"EMFB", C::None},    {"ECD", C::None},     {"EMAS", C::None},    {"EBHE", C::None},    {"CENT", C::None},
    {"NOE", C::None},     {"DG", C::Tensor},    {"FV", C::Index},     {"UVARM", C::Index},  {"SE", C::Vector},
    {"SK", C::Vector}};

// Contact: stresses (CSTRESS = CPRESS + CSHEAR1/2), relative displacements (CDISP = COPEN +
// CSLIP1/2), status, areas and resultant forces/moments and their centres (Abaqus); CDIS,
// CSTR, CELS, CNUM, PCON are CalculiX keys (CF, CFN, CFS are shared with Abaqus).
constexpr Variable kContact[] = {
    {"CSTRESS", C::None}, {"CPRESS", C::None},  {"CSHEAR1", C::None}, {"CSHEAR2", C::None},
    {"CDSTRESS", C::None}, {"CDISP", C::None},  {"COPEN", C::None},   {"CSLIP1", C::None},   {"CSLIP2", C::None},
    {"CSTATUS", C::None}, {"CFORCE", C::None},  {"CNORMF", C::Vector}, {"CSHEARF", C::Vector}, {"CFN", C::Vector},
    {"CFS", C::Vector},   {"CFT", C::Vector},   {"CMN", C::Vector},   {"CMS", C::Vector},    {"CMT", C::Vector},
    {"CFNM", C::None},    {"CFSM", C::None},    {"CFTM", C::None},    {"CAREA", C::None},    {"CNAREA", C::None},
    {"XN", C::Vector},    {"XS", C::Vector},    {"XT", C::Vector},    {"CTRQ", C::None},     {"CSDMG", C::None},
    {"BDSTAT", C::None},  {"CDIS", C::None},    {"CSTR", C::None},    {"CELS", C::None},     {"CNUM", C::None},
    {"PCON", C::None},    {"CF", C::Vector}};

std::span<const Variable> table(OutputDomain d) {
  switch (d) {
    case OutputDomain::Node: return kNode;
    case OutputDomain::Element: return kElement;
    case OutputDomain::Contact: return kContact;
  }
  return {};
}

bool component_ok(Components c, std::string_view digits) {
  switch (c) {
    case C::None: return false;
    case C::Vector: return digits.size() == 1 && digits[0] >= '1' && digits[0] <= '3';
    case C::Tensor:
      return digits == "11" || digits == "22" || digits == "33" || digits == "12" || digits == "13" || digits == "23";
    case C::Index: return !digits.empty() && digits[0] != '0';
  }
  return false;
}

}  // namespace

bool is_output_variable(OutputDomain domain, std::string_view name) {
  const auto vars = table(domain);
  auto find = [&](std::string_view n) {
    return std::find_if(vars.begin(), vars.end(), [&](const Variable& v) { return v.name == n; });
  };
  if (find(name) != vars.end()) return true;
  std::size_t base_len = name.size();
  while (base_len > 0 && std::isdigit(static_cast<unsigned char>(name[base_len - 1]))) --base_len;
  if (base_len == name.size() || base_len == 0) return false;
  auto it = find(name.substr(0, base_len));
  return it != vars.end() && component_ok(it->components, name.substr(base_len));
}

std::string canonical_output_name(OutputDomain domain, std::string_view name) {
  const bool calculix_key = name.starts_with("CDIS") || name.starts_with("CSTR");
  if (domain == OutputDomain::Contact && calculix_key && !is_output_variable(domain, name)) return std::string(name.substr(0, 4));
  return std::string(name);
}

std::vector<std::string> output_variable_names(OutputDomain domain) {
  std::vector<std::string> out;
  for (const Variable& v : table(domain)) out.emplace_back(v.name);
  return out;
}

}  // namespace inpact::parser
