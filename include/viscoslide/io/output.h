// SPDX-License-Identifier: LGPL-2.1-or-later
// Files of a run: the output directory, CSV tables, VTU/PVTU fields with
// their .pvd collections, and the provenance of the run.
#ifndef viscoslide_output_h
#define viscoslide_output_h

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/mpi.h>

#include <deal.II/numerics/data_out.h>

#include <viscoslide/io/input.h>

#include <chrono>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace viscoslide
{
  using namespace dealii;

  namespace Parameters
  {
    enum class Verbosity
    {
      quiet,
      normal,
      verbose
    };
    VISCOSLIDE_CHOICES(Verbosity, "quiet", "normal", "verbose")

    enum class FieldFormat
    {
      vtu,
      hdf5
    };
    VISCOSLIDE_CHOICES(FieldFormat, "vtu", "hdf5")

    // The 'Output' section.
    struct Output
    {
      std::string  directory;
      Verbosity    verbosity;
      unsigned int fields_every;
      unsigned int profile_every;
      unsigned int checkpoint_every; // sliding steps; 0: none
      bool         write_fields;
      FieldFormat  field_format;

      static void
      declare(ParameterHandler &prm);
      void
      parse(ParameterHandler &prm);
    };
  } // namespace Parameters


  // A CSV file with a header line, written by rank 0 only. Each row is
  // flushed as it is added so that a killed run keeps every finished step.
  // The columns are declared once, by the constructor; a row names each
  // value's column, and a row whose names differ from the columns is an
  // error (std::logic_error) in every build.
  class CsvTable
  {
  public:
    // (column, value) in the order of the columns.
    using Row = std::vector<std::pair<std::string, std::string>>;

    // A column written after the declared ones: the value of column
    // `from` times `factor` (the same quantity in SI units, units.h).
    struct Derived
    {
      std::string from, name;
      double      factor;
    };

    // `derived` columns whose `from` is not a column are left out.
    CsvTable(const std::string              &filename,
             const std::vector<std::string> &columns,
             const std::string              &comment,
             MPI_Comm                        comm,
             const std::vector<Derived>     &derived = {});

    // Reopens a table written by the constructor above, keeping its first
    // `keep_rows` rows (those of a checkpoint) and appending after them.
    CsvTable(const std::string              &filename,
             const std::vector<std::string> &columns,
             std::size_t                     keep_rows,
             MPI_Comm                        comm,
             const std::vector<Derived>     &derived = {});

    // The header of a table with these columns and derived columns: the
    // columns, then the derived ones whose source is among them.
    static std::vector<std::string>
    header(const std::vector<std::string> &columns,
           const std::vector<Derived>     &derived);

    void
    add_row(const Row &row);

    // The rows written, those kept by the reopening constructor included.
    std::size_t
    n_rows() const
    {
      return rows;
    }

    // Numbers are written with 12 significant digits.
    static std::string
    format(double value);

    // The rows of a table written by this class, as column -> value maps
    // (none if the file cannot be read).
    static std::vector<std::map<std::string, std::string>>
    read(const std::string &filename);

  private:
    std::unique_ptr<std::ofstream> file;
    std::vector<std::string>       columns;
    // The derived columns: the position of their source column, the factor.
    std::vector<std::pair<std::size_t, double>> derived;
    std::size_t                                 rows = 0;
  };


  // While it lives, what the program prints on std::cout also goes into
  // `file` (a run's log.txt), or with `to_screen` = false only there (the
  // cases of a study run side by side); what it prints on std::cerr goes
  // into the file and, always, to the screen. `append`: a resumed run
  // continues its log.
  class ScreenLog
  {
  public:
    ScreenLog(const std::string &file, bool to_screen, bool append);
    ~ScreenLog();
    ScreenLog(const ScreenLog &) = delete;
    ScreenLog &
    operator=(const ScreenLog &) = delete;

  private:
    class Tee;
    std::ofstream        file;
    std::unique_ptr<Tee> tee, error_tee;
    std::streambuf      *screen, *error_screen;
  };


  class OutputWriter
  {
  public:
    // format: "vtu" (one .vtu per process, .pvtu, .pvd) or "hdf5" (one
    // .h5 per step written by all processes, .xdmf collection).
    OutputWriter(const std::string            &directory,
                 MPI_Comm                      comm,
                 const Parameters::FieldFormat format);

    // Creates the directory. Refuses (throws) if it already holds the
    // results of a run and overwriting was not asked for.
    static void
    prepare_directory(const std::string &directory,
                      bool               overwrite,
                      MPI_Comm           comm);

    std::string
    path(const std::string &filename) const;

    // Writes DataOut(Faces) patches of step `counter` as NAME_NNNNN.pvtu
    // (+ one .vtu per process) or NAME_NNNNN.h5, and rewrites the
    // collection NAME.pvd or NAME.xdmf that lists them with their times.
    template <typename DataOutType>
    void
    write(const DataOutType &data_out,
          const std::string &name,
          unsigned int       counter,
          double             time);

    // A resumed run: takes the entries of an existing NAME.pvd (NAME.xdmf)
    // written before step `before` back into the collection it extends.
    void
    resume_collection(const std::string &name, unsigned int before);

  private:
    std::string             directory;
    MPI_Comm                comm;
    Parameters::FieldFormat format;
    // Per collection: (time, file) of each .pvtu, or (counter, <Grid>
    // element) of each .h5.
    std::map<std::string, std::vector<std::pair<double, std::string>>> records;
  };


  // How far a run (or a sweep of runs) has come, for one-line reports:
  // case k of n, the fraction of the current case done, the elapsed and an
  // estimate of the remaining wall time. The estimate assumes the cases
  // still to run cost as much as those run so far.
  class Progress
  {
  public:
    // n_cases: cases in the sweep; n_to_run: of them, those this
    // invocation runs (the others finished earlier).
    Progress(unsigned int n_cases, unsigned int n_to_run);

    // k counts from 1 among all cases.
    void
    start_case(unsigned int k, const std::string &name);

    // The current case continues from a checkpoint with this fraction
    // already done, which the time estimate leaves out of the rate.
    void
    resume_case(double fraction_done);

    // E.g. "case 3/12 muT1_t100: 26 %, 5 min elapsed, ~14 min left".
    std::string
    report(double case_fraction) const;

  private:
    unsigned int                          n_cases, n_to_run;
    unsigned int                          k       = 0;
    unsigned int                          n_begun = 0;
    std::string                           name;
    double                                done_before = 0;
    std::chrono::steady_clock::time_point start;
  };


  // How far an approach is and what it may still take, for its step lines.
  // It ends at delta_final, or where F_n passes a target load: the steps
  // left are then extrapolated from the last step's rise of F_n (else
  // counted in increments to delta_final), and their time from the mean
  // step so far. E.g. "approach 40 %, 12 s elapsed, ~18 s left".
  class ApproachProgress
  {
  public:
    // Lengths in any one unit; target_force NaN: none.
    ApproachProgress(double delta_final, double increment, double target_force);

    // After a converged step at delta with normal force F.
    std::string
    report(double delta, double F);

  private:
    double       delta_final, increment, target_force;
    double       last_force = std::numeric_limits<double>::quiet_NaN();
    unsigned int steps      = 0;
    std::chrono::steady_clock::time_point start =
      std::chrono::steady_clock::now();
  };


  // Writes `text` to `path` through a temporary file and a rename, so
  // that a killed run leaves the old or the new file, never half of one.
  void
  write_atomically(const std::string &path, const std::string &text);

  // A wall time as the progress lines show it: "42.0 s", "12.5 min", "3 h".
  std::string
  format_duration(double seconds);

  // The text that identifies the program version in every output.
  std::string
  version_string();
} // namespace viscoslide

#endif
