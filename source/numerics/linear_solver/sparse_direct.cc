// SPDX-License-Identifier: LGPL-2.1-or-later
// The sparse direct solver: MUMPS on the assembled matrix, with its Schur
// complement on a set of unknowns.
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <viscoslide/io/output.h>
#include <viscoslide/numerics/heartbeat.h>
#include <viscoslide/numerics/linear_solver.h>

#include <Epetra_CrsMatrix.h>
#include <dmumps_c.h>

#include <algorithm>
#include <string>

namespace viscoslide
{
  using Vector = TrilinosWrappers::MPI::Vector;

  namespace
  {
    // f(local row, local column, value) for every locally owned entry of A,
    // row by row: the order of MUMPS's coordinate arrays.
    template <typename Function>
    void
    for_each_local_entry(const Epetra_CrsMatrix &A, const Function &f)
    {
      for (int r = 0; r < A.NumMyRows(); ++r)
        {
          int     n;
          double *v;
          int    *c;
          A.ExtractMyRowView(r, n, v, c);
          for (int j = 0; j < n; ++j)
            f(r, c[j], v[j]);
        }
    }
  } // namespace

  struct SparseDirect::Mumps
  {
    DMUMPS_STRUC_C id{};

    MUMPS_INT &
    icntl(const unsigned int i)
    {
      return id.icntl[i - 1];
    }
    MUMPS_INT
    infog(const unsigned int i) const
    {
      return id.infog[i - 1];
    }
  };


  SparseDirect::SparseDirect(const MPI_Comm comm)
    : comm(comm)
  {
  }


  SparseDirect::~SparseDirect()
  {
    clear();
  }


  void
  SparseDirect::clear()
  {
    if (mumps)
      {
        mumps->id.job = -2;
        dmumps_c(&mumps->id);
        mumps.reset();
      }
  }


  void
  SparseDirect::call(const int job, const char *what)
  {
    mumps->id.job = job;
    dmumps_c(&mumps->id);
    AssertThrow(mumps->infog(1) >= 0,
                ExcMessage(std::string("MUMPS failed in its ") + what +
                           " (INFOG(1) = " + std::to_string(mumps->infog(1)) +
                           ", INFOG(2) = " + std::to_string(mumps->infog(2)) +
                           ")"));
  }


  // The pattern of the locally owned rows in coordinate format, the Schur
  // unknowns, and the analysis.
  void
  SparseDirect::analyse(const TrilinosWrappers::SparseMatrix &matrix,
                        const std::vector<int>               &T)
  {
    clear();
    AssertThrow(!T.empty(),
                ExcMessage("The direct solver needs surface unknowns"));
    const Epetra_CrsMatrix &A = matrix.trilinos_matrix();
    mumps                     = std::make_unique<Mumps>();
    auto &id                  = mumps->id;
    id.comm_fortran           = static_cast<MUMPS_INT>(MPI_Comm_c2f(comm));
    id.par                    = 1; // the host works too
    id.sym                    = 0;
    call(-1, "initialization");
    mumps->icntl(1)  = -1; // no messages
    mumps->icntl(2)  = -1;
    mumps->icntl(3)  = -1;
    mumps->icntl(4)  = 0;
    mumps->icntl(14) = 30; // workspace beyond the estimate, percent
    mumps->icntl(18) = 3;  // each process gives its rows
    mumps->icntl(19) = 1;  // the Schur complement on the host, by rows
    mumps->icntl(20) = 0;  // dense right-hand side on the host
    mumps->icntl(21) = 0;  // solution on the host
    // Rows and columns scaled by their largest entries, once: the strain
    // rows of the steady state scale with cell area (1e6 apart), and
    // MUMPS's default, an iterative scaling, costs a tenth of each
    // factorization for no change in the solutions.
    mumps->icntl(8) = 4;

    // The global indices, 1-based, looked up once per row and column
    // rather than once per entry.
    const auto one_based = [](const Epetra_BlockMap &map) {
      std::vector<int> index(map.NumMyElements());
      for (int i = 0; i < map.NumMyElements(); ++i)
        index[i] = static_cast<int>(map.GID64(i)) + 1;
      return index;
    };
    const std::vector<int> row_index    = one_based(A.RowMap()),
                           column_index = one_based(A.ColMap());
    rows.clear();
    columns.clear();
    for_each_local_entry(A, [&](const int r, const int c, double) {
      rows.push_back(row_index[r]);
      columns.push_back(column_index[c]);
    });
    values.resize(rows.size());
    id.n            = static_cast<MUMPS_INT>(A.NumGlobalRows64());
    id.nnz_loc      = rows.size();
    id.nz_loc       = static_cast<MUMPS_INT>(rows.size());
    id.irn_loc      = rows.data();
    id.jcn_loc      = columns.data();
    id.a_loc        = values.data();
    const bool host = Utilities::MPI::this_mpi_process(comm) == 0;
    schur_list.clear();
    if (host)
      for (const int t : T)
        schur_list.push_back(t + 1);
    id.size_schur    = static_cast<MUMPS_INT>(T.size());
    id.listvar_schur = schur_list.data();
    schur.assign(host ? T.size() * T.size() : 1, 0.);
    id.schur     = schur.data();
    id.schur_lld = static_cast<MUMPS_INT>(T.size());
    call(1, "analysis");

    // Where each process's rows go in the gathered right-hand side: deal.II
    // gives each process one contiguous range.
    const int first = static_cast<int>(A.RowMap().MinMyGID64());
    const int count = A.NumMyRows();
    AssertThrow(count == 0 || A.RowMap().MaxMyGID64() - first + 1 == count,
                ExcMessage("The direct solver needs contiguous row ranges"));
    counts  = Utilities::MPI::all_gather(comm, count);
    offsets = Utilities::MPI::all_gather(comm, count > 0 ? first : 0);
    gathered.assign(host ? id.n : 1, 0.);
    reduced.assign(T.size(), 0.);
  }


  void
  SparseDirect::factorize(const TrilinosWrappers::SparseMatrix &matrix)
  {
    const Epetra_CrsMatrix &A = matrix.trilinos_matrix();
    std::size_t             k = 0;
    for_each_local_entry(A, [&](int, int, const double v) {
      if (k < values.size())
        values[k] = v;
      ++k;
    });
    AssertThrow(k == values.size(),
                ExcMessage("The matrix changed its pattern without clear()"));
    // The time left from the operations the analysis counted and the rate
    // of the factorizations before this one.
    const double estimated_flops = mumps->id.rinfog[0];
    Timer        timer;
    {
      const HeartbeatWhile progress(
        Utilities::MPI::this_mpi_process(comm) == 0, [&](const double s) {
          std::string line = "        MUMPS factorization of " +
                             std::to_string(mumps->id.n) +
                             " unknowns: " + format_duration(s) + " so far";
          if (flop_rate > 0)
            line +=
              ", ~" +
              format_duration(std::max(estimated_flops / flop_rate - s, 0.)) +
              " left";
          return line;
        });
      // A workspace too small for the pivoting that occurred: more, again.
      for (int attempt = 0;; ++attempt)
        {
          mumps->id.job = 2;
          dmumps_c(&mumps->id);
          const int e = mumps->infog(1);
          if (attempt < 4 && (e == -8 || e == -9 || e == -11 || e == -12 ||
                              e == -14 || e == -15 || e == -17 || e == -20))
            mumps->icntl(14) *= 2;
          else
            break;
        }
    }
    AssertThrow(mumps->infog(1) >= 0,
                ExcMessage("MUMPS failed in its factorization (INFOG(1) = " +
                           std::to_string(mumps->infog(1)) + ")"));
    flop_rate = mumps->id.rinfog[2] / std::max(timer.wall_time(), 1e-3);
  }


  std::vector<double>
  SparseDirect::reduce(const Vector &b)
  {
    MPI_Gatherv(b.trilinos_vector()[0],
                counts[Utilities::MPI::this_mpi_process(comm)],
                MPI_DOUBLE,
                gathered.data(),
                counts.data(),
                offsets.data(),
                MPI_DOUBLE,
                0,
                comm);
    auto &id         = mumps->id;
    id.rhs           = gathered.data();
    id.nrhs          = 1;
    id.lrhs          = id.n;
    id.redrhs        = reduced.data();
    id.lredrhs       = id.size_schur;
    mumps->icntl(26) = 1;
    call(3, "reduction to the Schur unknowns");
    return reduced;
  }


  void
  SparseDirect::expand(const std::vector<double> &x_T, Vector &x)
  {
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      std::copy(x_T.begin(), x_T.end(), reduced.begin());
    mumps->icntl(26) = 2;
    call(3, "expansion from the Schur unknowns");
    mumps->icntl(26) = 0;
    MPI_Scatterv(gathered.data(),
                 counts.data(),
                 offsets.data(),
                 MPI_DOUBLE,
                 x.trilinos_vector()[0],
                 counts[Utilities::MPI::this_mpi_process(comm)],
                 MPI_DOUBLE,
                 0,
                 comm);
  }
} // namespace viscoslide
