#include <deal.II/base/revision.h>
#include <deal.II/base/utilities.h>

#include <deal.II/numerics/data_out_faces.h>

#include <viscoslide/output.h>
#include <viscoslide/parameters.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <regex>
#include <sstream>

#ifndef VISCOSLIDE_VERSION
#define VISCOSLIDE_VERSION "unknown"
#endif
#ifndef VISCOSLIDE_GIT_REVISION
#define VISCOSLIDE_GIT_REVISION "unknown"
#endif

namespace viscoslide
{
  CsvTable::CsvTable(const std::string              &filename,
                     const std::vector<std::string> &columns,
                     const std::string              &comment,
                     MPI_Comm                        comm)
    : n_columns(columns.size())
  {
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    file = std::make_unique<std::ofstream>(filename);
    if (!*file)
      throw Parameters::ExcInvalidInput("cannot open '" + filename +
                                        "' for writing");
    if (!comment.empty())
      *file << "# " << comment << '\n';
    for (std::size_t i = 0; i < columns.size(); ++i)
      *file << (i ? "," : "") << columns[i];
    *file << std::endl;
  }

  void
  CsvTable::add_row(const std::vector<std::string> &values)
  {
    AssertDimension(values.size(), n_columns);
    if (!file)
      return;
    for (std::size_t i = 0; i < values.size(); ++i)
      *file << (i ? "," : "") << values[i];
    *file << std::endl;
    if (!*file)
      throw std::runtime_error("writing a row of a CSV file failed (disk "
                               "full?)");
  }

  CsvTable::CsvTable(const std::string              &filename,
                     const std::vector<std::string> &columns,
                     const std::size_t               keep_rows,
                     MPI_Comm                        comm)
    : n_columns(columns.size())
  {
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    std::ifstream in(filename);
    if (!in)
      throw Parameters::ExcInvalidInput("cannot read '" + filename +
                                        "' to continue it");
    std::string kept, line;
    std::size_t rows        = 0;
    bool        header_seen = false;
    while (std::getline(in, line))
      {
        const bool comment = !line.empty() && line[0] == '#';
        if (header_seen && !comment && rows == keep_rows)
          break; // rows written after the checkpoint
        kept += line + '\n';
        if (comment)
          continue;
        if (header_seen)
          ++rows;
        header_seen = true;
      }
    if (rows < keep_rows)
      throw Parameters::ExcInvalidInput(
        "'" + filename + "' holds " + std::to_string(rows) +
        " rows, fewer than the " + std::to_string(keep_rows) +
        " of the checkpoint");
    in.close();
    write_atomically(filename, kept);
    file = std::make_unique<std::ofstream>(filename, std::ios::app);
    if (!*file)
      throw Parameters::ExcInvalidInput("cannot open '" + filename +
                                        "' for writing");
  }

  std::string
  CsvTable::format(const double value)
  {
    std::ostringstream s;
    s << std::setprecision(12) << value;
    return s.str();
  }


  OutputWriter::OutputWriter(const std::string &directory, MPI_Comm comm)
    : directory(directory)
    , comm(comm)
  {
  }

  void
  OutputWriter::prepare_directory(const std::string &directory,
                                  const bool         overwrite,
                                  MPI_Comm           comm)
  {
    namespace fs = std::filesystem;
    std::string error;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::error_code ec;
        if (fs::exists(fs::path(directory) / "parameters.prm") && !overwrite)
          error = "output directory '" + directory +
                  "' already holds the results of a run; choose another "
                  "'Output/Output directory' or run with --overwrite";
        else if (fs::create_directories(directory, ec), ec)
          error = "cannot create output directory '" + directory +
                  "': " + ec.message();
        else
          {
            // Fail now, not at the first write hours later.
            const auto    probe = fs::path(directory) / ".write_test";
            std::ofstream test(probe);
            if (!(test << "x"))
              error = "output directory '" + directory + "' is not writable";
            test.close();
            fs::remove(probe, ec);
          }
      }
    error = Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw Parameters::ExcInvalidInput(error);
  }

  std::string
  OutputWriter::path(const std::string &filename) const
  {
    return (std::filesystem::path(directory) / filename).string();
  }

  template <typename DataOutType>
  void
  OutputWriter::write_pvtu(const DataOutType &data_out,
                           const std::string &name,
                           const unsigned int counter,
                           const double       time)
  {
    const std::string pvtu = data_out.write_vtu_with_pvtu_record(
      directory + "/", name, counter, comm, 5, 0);
    auto &records = pvd_records[name];
    records.emplace_back(time, pvtu);
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::ostringstream pvd;
        DataOutBase::write_pvd_record(pvd, records);
        write_atomically(path(name + ".pvd"), pvd.str());
      }
  }


  void
  OutputWriter::resume_collection(const std::string &name,
                                  const unsigned int before)
  {
    auto &records = pvd_records[name];
    records.clear();
    std::ifstream    in(path(name + ".pvd"));
    const std::regex dataset("timestep=\"([^\"]*)\".*file=\"(" + name +
                             "_([0-9]+)\\.pvtu)\"");
    std::string      line;
    std::smatch      m;
    while (std::getline(in, line))
      if (std::regex_search(line, m, dataset) &&
          std::stoul(m[3].str()) < before)
        records.emplace_back(std::stod(m[1].str()), m[2].str());
  }

  template void
  OutputWriter::write_pvtu(const DataOut<2> &,
                           const std::string &,
                           unsigned int,
                           double);
  template void
  OutputWriter::write_pvtu(const DataOutFaces<2> &,
                           const std::string &,
                           unsigned int,
                           double);


  Progress::Progress(const unsigned int n_cases, const unsigned int n_to_run)
    : n_cases(n_cases)
    , n_to_run(std::max(n_to_run, 1u))
    , start(std::chrono::steady_clock::now())
  {
  }

  void
  Progress::start_case(const unsigned int k, const std::string &name)
  {
    this->k    = k;
    this->name = name;
    ++n_begun;
  }

  namespace
  {
    std::string
    duration(const double seconds)
    {
      std::ostringstream s;
      s << std::fixed << std::setprecision(seconds < 600 ? 1 : 0);
      if (seconds < 120)
        s << seconds << " s";
      else if (seconds < 7200)
        s << seconds / 60 << " min";
      else
        s << seconds / 3600 << " h";
      return s.str();
    }
  } // namespace

  std::string
  Progress::report(const double case_fraction) const
  {
    const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    const double done =
      (n_begun > 0 ? n_begun - 1 : 0) + std::clamp(case_fraction, 0., 1.);
    std::ostringstream s;
    if (n_cases > 1)
      s << "case " << k << "/" << n_cases << " " << name << ": ";
    s << std::fixed << std::setprecision(0) << 100 * case_fraction << " %, "
      << duration(elapsed) << " elapsed";
    if (done > 0.02)
      s << ", ~" << duration(elapsed / done * (n_to_run - done)) << " left";
    return s.str();
  }


  void
  write_atomically(const std::string &path, const std::string &text)
  {
    const std::string tmp = path + ".tmp";
    {
      std::ofstream out(tmp);
      out << text;
      out.flush();
      if (!out)
        throw std::runtime_error("cannot write '" + tmp + "' (disk full?)");
    }
    std::filesystem::rename(tmp, path);
  }


  std::string
  version_string()
  {
    return std::string("viscoslide ") + VISCOSLIDE_VERSION + " (git " +
           VISCOSLIDE_GIT_REVISION + ", deal.II " + DEAL_II_PACKAGE_VERSION +
           ")";
  }
} // namespace viscoslide
