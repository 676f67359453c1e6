// The active-set step shared by the capped contact references (capped_sphere.cpp,
// capped_cylinder.cpp): each element (ring, strip) of the discretised surface is free (p = 0, gap
// ≥ 0), elastic (gap = 0) or plastic (p = p_cap, gap ≤ 0). Internal to contact/reference.
#pragma once

#include <Eigen/Core>

#include <set>
#include <vector>

namespace tribo::contact::reference {

enum class Element { free, elastic, plastic };

// Moves the elements whose solution p (pressures, the elastic ones solved) and gap contradict their
// set: removals first (an elastic element with p out of [0, p_cap]); only when none is due,
// additions (a free element penetrated, a plastic one clear) — updating both at once makes the edge
// element cycle. Tolerances keep round-off from flipping one. Returns whether the sets changed to a
// state not seen before: a state seen before means the edge element alternates between two states
// whose solutions each put it on the other side — the discrete edge lies inside it, and either is
// the answer to within that element.
inline bool update_active_sets(std::vector<Element>& state, const Eigen::VectorXd& p, const Eigen::VectorXd& gap, double cap,
                               double p_tol, double gap_tol, std::set<std::vector<Element>>& seen) {
  const int n = static_cast<int>(state.size());
  bool changed = false;
  for (int i = 0; i < n; ++i) {
    if (state[i] != Element::elastic) continue;
    const Element next = p(i) < -p_tol ? Element::free : p(i) > cap + p_tol ? Element::plastic : Element::elastic;
    changed |= next != state[i];
    state[i] = next;
  }
  if (!changed)
    for (int i = 0; i < n; ++i) {
      const bool wrong = (state[i] == Element::free && gap(i) < -gap_tol) || (state[i] == Element::plastic && gap(i) > gap_tol);
      if (wrong) state[i] = Element::elastic;
      changed |= wrong;
    }
  return changed && seen.insert(state).second;
}

}  // namespace tribo::contact::reference
