// SPDX-License-Identifier: LGPL-2.1-or-later
// What a case's parameters are checked against once every section has read
// its own entries: the entries that must agree across sections, what the
// mesh and the physics can represent, the block fitted to the wake of the
// fastest speed, and the warnings of what is legal but known to be
// inaccurate. Called by Parameters::AllParameters::parse.
#ifndef viscoslide_case_setup_h
#define viscoslide_case_setup_h

namespace viscoslide
{
  namespace Parameters
  {
    struct AllParameters;
  }

  namespace CaseSetup
  {
    // Entries of different sections that contradict each other; builds the
    // indenter once so that an unreadable table or a bad expression is
    // reported with the other input errors, before a run.
    void
    check_consistency(const Parameters::AllParameters &p);

    // 'Boundary element/Grid' = automatic: the nested grid on the 3D
    // half-space where the uniform grid would not resolve the adhesive
    // zone, the uniform grid elsewhere; 'Refinement' = 0 made the least
    // that resolves it; the choice said in p.notes.
    void
    choose_surface_grid(Parameters::AllParameters &p);

    // In 3D, 'Solver/Linear solver' = automatic keeps the direct solver
    // only up to the unknowns whose factors fit the machines' memory; then
    // refuses a finite-element case that fits with neither solver.
    void
    fit_linear_solver_to_memory(Parameters::AllParameters &p);

    // Widens (and deepens) the block to hold the wake of the fastest speed
    // where the control allows it; says so in p.notes.
    void
    fit_block_to_wake(Parameters::AllParameters &p);

    // Refuses, before a mesh is built, what the refinement cannot
    // represent and a block the contact does not fit in.
    void
    check_mesh_can_hold_case(const Parameters::AllParameters &p);

    // Legal but known to be inaccurate: added to p.notes, said when the
    // case starts.
    void
    warn_about_accuracy(Parameters::AllParameters &p);
  } // namespace CaseSetup
} // namespace viscoslide

#endif
