// SPDX-License-Identifier: LGPL-2.1-or-later
#include <deal.II/base/revision.h>
#include <deal.II/base/utilities.h>

#include <deal.II/numerics/data_out_faces.h>

#include <viscoslide/io/output.h>
#include <viscoslide/io/parameters.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <regex>
#include <sstream>

#include <unistd.h>

#ifndef VISCOSLIDE_VERSION
#define VISCOSLIDE_VERSION "unknown"
#endif
#include <viscoslide_revision.h> // generated at build time (CMakeLists.txt)

namespace viscoslide
{
  namespace
  {
    // The cell shape of a DataOut's patches (quadrilaterals of the volume,
    // lines of the surface), for XDMF.
    template <int patch_dim, int spacedim>
    ReferenceCell
    patch_cell(const DataOutInterface<patch_dim, spacedim> &)
    {
      return ReferenceCells::get_hypercube<patch_dim>();
    }

    // Of the derived columns (see CsvTable::Derived), those whose source
    // is one of `columns`: the position of the source and the factor.
    std::vector<std::pair<std::size_t, double>>
    locate_derived(const std::vector<std::string>       &columns,
                   const std::vector<CsvTable::Derived> &derived)
    {
      std::vector<std::pair<std::size_t, double>> sources;
      for (const auto &d : derived)
        {
          const auto from = std::find(columns.begin(), columns.end(), d.from);
          if (from != columns.end())
            sources.emplace_back(from - columns.begin(), d.factor);
        }
      return sources;
    }
  } // namespace


  std::vector<std::string>
  CsvTable::header(const std::vector<std::string> &columns,
                   const std::vector<Derived>     &derived)
  {
    std::vector<std::string> names = columns;
    for (const auto &d : derived)
      if (std::find(columns.begin(), columns.end(), d.from) != columns.end())
        names.push_back(d.name);
    return names;
  }


  CsvTable::CsvTable(const std::string              &filename,
                     const std::vector<std::string> &columns,
                     const std::string              &comment,
                     MPI_Comm                        comm,
                     const std::vector<Derived>     &derived_columns)
    : columns(columns)
  {
    derived = locate_derived(columns, derived_columns);
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    file = std::make_unique<std::ofstream>(filename);
    if (!*file)
      throw Parameters::ExcInvalidInput("cannot open '" + filename +
                                        "' for writing");
    if (!comment.empty())
      *file << "# " << comment << '\n';
    const auto names = header(columns, derived_columns);
    for (std::size_t i = 0; i < names.size(); ++i)
      *file << (i ? "," : "") << names[i];
    *file << std::endl;
  }

  void
  CsvTable::add_row(const Row &row)
  {
    // Checked in every build: a row that does not name the table's columns
    // in their order would silently shift values between columns.
    bool matches = row.size() == columns.size();
    for (std::size_t i = 0; matches && i < row.size(); ++i)
      matches = row[i].first == columns[i];
    if (!matches)
      {
        std::string names;
        for (const auto &cell : row)
          names += (names.empty() ? "" : ",") + cell.first;
        throw std::logic_error("a row with the columns " + names +
                               " was added to a table whose columns differ");
      }
    ++rows;
    if (!file)
      return;
    for (std::size_t i = 0; i < row.size(); ++i)
      *file << (i ? "," : "") << row[i].second;
    // A derived value of a cell that is not a number (a label) is empty.
    for (const auto &[from, factor] : derived)
      {
        char        *end   = nullptr;
        const auto  &cell  = row[from].second;
        const double value = std::strtod(cell.c_str(), &end);
        *file << ','
              << (cell.empty() || *end != '\0' ? "" : format(value * factor));
      }
    *file << std::endl;
    if (!*file)
      throw std::runtime_error("writing a row of a CSV file failed (disk "
                               "full?)");
  }

  std::vector<std::map<std::string, std::string>>
  CsvTable::read(const std::string &filename)
  {
    std::vector<std::map<std::string, std::string>> rows;
    std::ifstream                                   in(filename);
    std::string                                     line;
    std::vector<std::string>                        header;
    while (std::getline(in, line))
      {
        if (line.empty() || line[0] == '#')
          continue;
        const auto values = Utilities::split_string_list(line, ',');
        if (header.empty())
          {
            header = values;
            continue;
          }
        std::map<std::string, std::string> row;
        for (std::size_t i = 0; i < header.size() && i < values.size(); ++i)
          row[header[i]] = values[i];
        rows.push_back(row);
      }
    return rows;
  }


  CsvTable::CsvTable(const std::string              &filename,
                     const std::vector<std::string> &columns,
                     const std::size_t               keep_rows,
                     MPI_Comm                        comm,
                     const std::vector<Derived>     &derived_columns)
    : columns(columns)
    , rows(keep_rows)
  {
    derived = locate_derived(columns, derived_columns);
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


  OutputWriter::OutputWriter(const std::string            &directory,
                             MPI_Comm                      comm,
                             const Parameters::FieldFormat format)
    : directory(directory)
    , comm(comm)
    , format(format)
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

  class ScreenLog::Tee : public std::streambuf
  {
  public:
    Tee(std::streambuf *screen, std::streambuf *file)
      : screen(screen)
      , file(file)
    {
    }

  protected:
    int
    overflow(const int c) override
    {
      if (c == traits_type::eof())
        return traits_type::not_eof(c);
      if (file->sputc(c) == traits_type::eof() ||
          (screen != nullptr && screen->sputc(c) == traits_type::eof()))
        return traits_type::eof();
      return c;
    }

    std::streamsize
    xsputn(const char *s, const std::streamsize n) override
    {
      file->sputn(s, n);
      if (screen != nullptr)
        screen->sputn(s, n);
      return n;
    }

    int
    sync() override
    {
      const int a = file->pubsync();
      const int b = screen != nullptr ? screen->pubsync() : 0;
      return a == 0 && b == 0 ? 0 : -1;
    }

  private:
    std::streambuf *screen, *file;
  };


  ScreenLog::ScreenLog(const std::string &filename,
                       const bool         to_screen,
                       const bool         append)
    : file(filename, append ? std::ios::app : std::ios::trunc)
    , screen(std::cout.rdbuf())
    , error_screen(std::cerr.rdbuf())
  {
    // Without its log the run goes on, on the screen as before.
    if (!file)
      return;
    std::cout.flush();
    tee = std::make_unique<Tee>(to_screen ? screen : nullptr, file.rdbuf());
    std::cout.rdbuf(tee.get());
    error_tee = std::make_unique<Tee>(error_screen, file.rdbuf());
    std::cerr.rdbuf(error_tee.get());
  }


  ScreenLog::~ScreenLog()
  {
    std::cout.flush();
    std::cout.rdbuf(screen);
    std::cerr.rdbuf(error_screen);
  }


  std::string
  OutputWriter::path(const std::string &filename) const
  {
    return (std::filesystem::path(directory) / filename).string();
  }

  template <typename DataOutType>
  void
  OutputWriter::write(const DataOutType &data_out,
                      const std::string &name,
                      const unsigned int counter,
                      const double       time)
  {
    const std::string  step = name + "_" + Utilities::int_to_string(counter, 5);
    auto              &entries = records[name];
    std::ostringstream collection;
    try
      {
        if (format == Parameters::FieldFormat::vtu)
          {
            entries.emplace_back(time,
                                 data_out.write_vtu_with_pvtu_record(
                                   directory + "/", name, counter, comm, 5, 0));
            DataOutBase::write_pvd_record(collection, entries);
          }
        else
          {
            // One file per step, so that a step is complete once written
            // and a resumed run can continue the collection.
            DataOutBase::DataOutFilter filter(
              DataOutBase::DataOutFilterFlags(true, true));
            data_out.write_filtered_data(filter);
            data_out.write_hdf5_parallel(filter, path(step + ".h5"), comm);
            entries.emplace_back(
              counter,
              data_out.create_xdmf_entry(filter, step + ".h5", time, comm)
                .get_xdmf_content(3, patch_cell(data_out)));
            collection << "<?xml version=\"1.0\" ?>\n"
                       << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
                       << "<Xdmf Version=\"2.0\">\n  <Domain>\n"
                       << "    <Grid Name=\"CellTime\" GridType=\"Collection\" "
                          "CollectionType=\"Temporal\">\n";
            for (const auto &e : entries)
              collection << e.second;
            collection << "    </Grid>\n  </Domain>\n</Xdmf>\n";
          }
      }
    catch (ExceptionBase &e)
      {
        // A field file that could not be written completely (full disk) is
        // removed, so that no truncated file is left behind.
        namespace fs = std::filesystem;
        std::error_code ec;
        for (const auto &f : fs::directory_iterator(directory, ec))
          if (f.path().filename().string().rfind(step + ".", 0) == 0)
            fs::remove(f.path(), ec);
        throw std::runtime_error("cannot write the fields '" + step +
                                 ".*' into '" + directory + "' (" +
                                 e.get_exc_name() +
                                 ": disk full?); the files written before "
                                 "are complete");
      }
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      write_atomically(path(name + (format == Parameters::FieldFormat::vtu
                                      ? ".pvd"
                                      : ".xdmf")),
                       collection.str());
  }
  template void
  OutputWriter::write(const DataOut<2> &,
                      const std::string &,
                      unsigned int,
                      double);
  template void
  OutputWriter::write(const DataOutFaces<2> &,
                      const std::string &,
                      unsigned int,
                      double);
  template void
  OutputWriter::write(const DataOut<3> &,
                      const std::string &,
                      unsigned int,
                      double);
  template void
  OutputWriter::write(const DataOutFaces<3> &,
                      const std::string &,
                      unsigned int,
                      double);


  void
  OutputWriter::resume_collection(const std::string &name,
                                  const unsigned int before)
  {
    auto &entries = records[name];
    entries.clear();
    std::ifstream in(
      path(name + (format == Parameters::FieldFormat::vtu ? ".pvd" : ".xdmf")));
    std::stringstream text;
    text << in.rdbuf();
    const std::string all = text.str();
    std::smatch       m;
    if (format == Parameters::FieldFormat::vtu)
      {
        const std::regex dataset("timestep=\"([^\"]*)\"[^\n]*file=\"(" + name +
                                 "_([0-9]+)\\.pvtu)\"");
        for (auto it = std::sregex_iterator(all.begin(), all.end(), dataset);
             it != std::sregex_iterator();
             ++it)
          if (std::stoul((*it)[3].str()) < before)
            entries.emplace_back(std::stod((*it)[1].str()), (*it)[2].str());
      }
    else
      {
        // The <Grid> elements of the steps, each naming its .h5 file.
        const std::regex grid("( *<Grid Name=\"mesh\"[\\s\\S]*?</Grid>\n)");
        const std::regex file(name + "_([0-9]+)\\.h5");
        for (auto it = std::sregex_iterator(all.begin(), all.end(), grid);
             it != std::sregex_iterator();
             ++it)
          {
            const std::string element = (*it)[1].str();
            if (std::regex_search(element, m, file) &&
                std::stoul(m[1].str()) < before)
              entries.emplace_back(std::stoul(m[1].str()), element);
          }
      }
  }



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

  void
  Progress::resume_case(const double fraction_done)
  {
    done_before += std::clamp(fraction_done, 0., 1.);
  }

  std::string
  format_duration(const double seconds)
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
      << format_duration(elapsed) << " elapsed";
    if (done - done_before > 0.02)
      s << ", ~"
        << format_duration(elapsed / (done - done_before) *
                           std::max(0., n_to_run - done))
        << " left";
    return s.str();
  }


  ApproachProgress::ApproachProgress(const double delta_final,
                                     const double increment,
                                     const double target_force)
    : delta_final(delta_final)
    , increment(std::abs(increment))
    , target_force(target_force)
  {
  }


  std::string
  ApproachProgress::report(const double delta, const double F)
  {
    ++steps;
    const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    double       steps_left = std::abs(delta_final - delta) / increment;
    const double rise       = F - last_force;
    if (!std::isnan(target_force) && rise > 0)
      steps_left = std::min(steps_left, std::max(0., target_force - F) / rise);
    last_force = F;
    std::ostringstream s;
    s << "approach " << std::fixed << std::setprecision(0)
      << 100. * steps / (steps + steps_left) << " %, "
      << format_duration(elapsed) << " elapsed, ~"
      << format_duration(elapsed / steps * steps_left) << " left";
    return s.str();
  }


  void
  write_atomically(const std::string &path, const std::string &text)
  {
    // A name of its own per process: two runs may write the same file.
    const std::string tmp = path + ".tmp." + std::to_string(::getpid());
    {
      std::ofstream out(tmp);
      out << text;
      out.flush();
      if (!out)
        {
          out.close();
          std::remove(tmp.c_str());
          throw std::runtime_error("cannot write '" + tmp + "' (disk full?)");
        }
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


  namespace Parameters
  {
    void
    Output::declare(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      prm.declare_entry("Output directory",
                        "output",
                        Patterns::DirectoryName(),
                        "Directory that receives every file of the run: "
                        "approach.csv, surface profiles, VTU/PVTU fields with "
                        "their .pvd collection, and the parameter set "
                        "actually used (parameters.prm, parameters.json). "
                        "An existing directory that already holds results "
                        "is refused unless the program is called with "
                        "--overwrite.");
      prm.declare_entry("Verbosity",
                        "normal",
                        Patterns::Selection(choice_pattern<Verbosity>()),
                        "'quiet': only the start and end of each case and "
                        "errors. 'normal': one line per step (approach) or "
                        "per speed (steady-state solver) with the progress "
                        "of the run: case k of n, sliding distance covered, "
                        "elapsed and estimated remaining time. 'verbose': "
                        "also every Newton residual and line-search step.");
      prm.declare_entry("Write fields",
                        "true",
                        Patterns::Bool(),
                        "Write VTU/PVTU volume and surface fields.");
      prm.declare_entry(
        "Field format",
        "vtu",
        Patterns::Selection(choice_pattern<FieldFormat>()),
        "'vtu': per step one .vtu per process and a .pvtu, listed in NAME.pvd "
        "(ParaView, VisIt). 'hdf5': per step one NAME_NNNNN.h5 written "
        "by all processes together (MPI-IO), listed in NAME.xdmf (ParaView, "
        "VisIt); fewer files for large runs on many processes.");
      prm.declare_entry("Fields every",
                        "10",
                        Patterns::Integer(0),
                        "Write fields every this many accepted steps (and "
                        "always after the last step). 0: only the last.");
      prm.declare_entry("Surface profile every",
                        "0",
                        Patterns::Integer(0),
                        "Write the surface profile CSV every this many "
                        "accepted steps (and always after the last step). "
                        "0: only the last.");
      prm.declare_entry(
        "Checkpoint every",
        "100",
        Patterns::Integer(0),
        "Transient sliding: write a checkpoint (mesh, solution, history, "
        "sliding position and steady-state window) into OUTPUT/checkpoint "
        "every this many sliding steps, so that `viscoslide --resume` "
        "continues a killed run from there (doc/restart.md). The "
        "steady-state solver writes one after every converged speed or load "
        "whatever the value above 0. The previous checkpoint is replaced "
        "only once the new one is complete. 0: none.");
      prm.leave_subsection();
    }

    void
    Output::parse(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      directory = prm.get("Output directory");
      verbosity =
        parse_choice<Verbosity>(prm.get("Verbosity"), "Output/Verbosity");
      write_fields     = prm.get_bool("Write fields");
      fields_every     = prm.get_integer("Fields every");
      field_format     = parse_choice<FieldFormat>(prm.get("Field format"),
                                               "Output/Field format");
      profile_every    = prm.get_integer("Surface profile every");
      checkpoint_every = prm.get_integer("Checkpoint every");
      prm.leave_subsection();
      require(!directory.empty(),
              "'Output/Output directory' must not be empty");
    }
  } // namespace Parameters
} // namespace viscoslide
