// SPDX-License-Identifier: LGPL-2.1-or-later
// steady_state.csv of a case: one row per steady sliding state that a
// solver reached (or failed to reach), written by every solver through the
// same columns, and printed with the energy balance (implemented in
// source/io/steady_state_table.cc; the columns are documented in
// doc/outputs.md).
#ifndef viscoslide_steady_state_table_h
#define viscoslide_steady_state_table_h

#include <deal.II/base/conditional_ostream.h>

#include <viscoslide/io/output.h>
#include <viscoslide/io/parameters.h>
#include <viscoslide/io/postprocessing.h>

#include <memory>
#include <string>
#include <vector>

namespace viscoslide
{
  using namespace dealii;

  // F_t V / D - 1 of a steady state: the traction law is conservative,
  // so the work of the x force on the indenter equals the dissipation
  // (doc/model.md, checks). NaN where mu_energy = D / (V |F_n|) < 1e-3
  // (the elastic limits), where the ratio is noise.
  double
  energy_balance(double tangential_force,
                 double normal_force,
                 double V,
                 double dissipation_rate);


  class SteadyStateTable
  {
  public:
    // The file is created by the first row.
    SteadyStateTable(const Parameters::AllParameters &prm,
                     const Scales                    &scales,
                     const std::string               &filename,
                     MPI_Comm                         comm);

    // The columns, also for the sweep driver's row of a case that failed
    // before writing its own: in 3D A_hat for L_hat and the contact's
    // extents x_trail/R, x_lead/R, y_half/R at the end.
    static std::vector<std::string>
    columns(int dimension);

    // The layer thickness in eps, infinite for a half-plane, so that the
    // column stays numeric.
    static double
    t_hat(const Parameters::AllParameters &prm);

    // A state at speed V_hat and approach delta (internal units) with the
    // surface quantities and the total dissipation rate. `steady` = false:
    // the state is the last converged one of a station that was not
    // reached; `distance` is the transient's sliding distance (0 for the
    // steady-state solver).
    void
    add_row(double                    V_hat,
            double                    delta,
            const SurfaceQuantities  &quantities,
            double                    dissipation_rate,
            bool                      steady,
            double                    distance,
            Parameters::SlidingSolver solver,
            ConditionalOStream       &out);

    // Continues the file of a resumed run after its first `keep_rows` rows.
    void
    resume(std::size_t keep_rows);

    std::size_t
    n_rows() const
    {
      return table ? table->n_rows() : 0;
    }

  private:
    const Parameters::AllParameters &prm;
    const Scales                    &scales;
    const std::string                filename;
    MPI_Comm                         comm;
    std::unique_ptr<CsvTable>        table;
  };
} // namespace viscoslide

#endif
