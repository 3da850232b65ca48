// SeaSpring — MIT licence.
/// \file checkpoint_file.h
/// \brief Restart files: CheckpointData (checkpoint_data.h) in HDF5, written atomically
///        (a temporary file in the same folder, renamed over the old one when complete), read
///        back with checks that name the file.
///
/// Layout: attribute `format` = "seaspring-restart", `format_version`; group /arrays with one
/// uint8 dataset per array (its name with '/' written as '.') and attribute `elem_size`;
/// /reals and /ints: datasets `values` with attribute `names` (one name per line); /texts:
/// attribute `names` and attributes t0, t1, ... in that order.
#pragma once

#include <string>

#include "core/checkpoint_data.h"

namespace seaspring::io {

/// Writes `d` to `path` atomically (path + ".tmp", then renamed).
void writeCheckpointFile(const std::string& path, const CheckpointData& d);
/// Reads a restart file; throws seaspring::Error naming the file when it is missing, not a
/// restart file, or of another format version.
CheckpointData readCheckpointFile(const std::string& path);

/// A file a restarted run continues (gauge CSV, ledger): when `path` exists and holds at
/// least `offset` bytes (what it held at the checkpoint), cuts it there and returns true (the
/// caller appends); otherwise returns false (the caller starts it afresh, e.g. in a new OUTDIR).
bool cutForResume(const std::string& path, long long offset);

}  // namespace seaspring::io
