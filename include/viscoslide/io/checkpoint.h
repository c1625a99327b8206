// SPDX-License-Identifier: LGPL-2.1-or-later
// The folder OUTPUT/checkpoint of a run, written as a whole: the solvers
// fill a temporary folder (the mesh with its vectors through p4est, and
// their scalars as state.bin), which then replaces the previous
// checkpoint, so that a kill at any moment leaves one complete checkpoint
// (doc/restart.md).
#ifndef viscoslide_checkpoint_h
#define viscoslide_checkpoint_h

#include <deal.II/base/mpi.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>

#include <functional>
#include <string>

namespace viscoslide
{
  namespace Checkpoint
  {
    // Whether the run in `directory` has a checkpoint to resume from (also
    // one left as checkpoint.old by a kill between the two renames).
    bool
    exists(const std::string &directory);

    // Creates the empty temporary folder and returns its path, on every
    // process; the mesh goes there.
    std::string
    begin(const std::string &directory, MPI_Comm comm);

    // Writes `state` (a binary archive) as state.bin into the temporary
    // folder and puts the folder in place of the previous checkpoint.
    void
    commit(const std::string &directory,
           const std::string &state,
           MPI_Comm           comm);

    // The checkpoint folder to read (taking back a checkpoint left as
    // checkpoint.old by a kill between the two renames) and in `state` the
    // contents of its state.bin; throws if there is none.
    std::string
    open(const std::string &directory, std::string &state, MPI_Comm comm);

    // Who wrote a checkpoint's state: the solver and the version of what it
    // serializes, raised whenever that changes. Written first and checked
    // when read, so that a solver never misreads another's checkpoint or
    // an older one of its own.
    struct Format
    {
      std::string  solver;
      unsigned int version;
    };

    // The contents of state.bin: the format, then what `save` writes.
    std::string
    pack(const Format                                                 &format,
         const std::function<void(boost::archive::binary_oarchive &)> &save);

    // Reads the contents of state.bin (of the checkpoint `folder`) through
    // `load` once its format is checked; Parameters::ExcInvalidInput naming
    // the folder if another solver or version wrote it, or it is damaged.
    void
    unpack(const std::string                                            &state,
           const std::string                                            &folder,
           const Format                                                 &format,
           const std::function<void(boost::archive::binary_iarchive &)> &load);

    // Removes the checkpoint of a finished run, with any folder a kill
    // left behind.
    void
    remove(const std::string &directory, MPI_Comm comm);
  } // namespace Checkpoint
} // namespace viscoslide

#endif
