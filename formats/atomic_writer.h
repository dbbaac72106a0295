// Atomic replacement of output files, for one output or a run of them.
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>

#include "processing/core/status.h"

namespace mocapfill {

// Each Write puts `parts` in a temporary file beside `path` and swaps it into place, so that
// `path` names a complete file at every instant and a failed write leaves it as it was.
// The file a write replaces ends up under the temporary name; a writer keeps it (its
// "spare") and overwrites it for its next output in the same folder, instead of unlinking
// it and creating a file anew: on ext4 without a journal, every new file's inode is found
// by stepping over the inodes freed in the last minutes, one buffer lookup each, with the
// folder locked meanwhile, which a batch that replaces its outputs would pay for every file
// (docs/performance.md). A spare is reused only while no other name links
// to it, no process has it open (or mapped) and this user owns it, and it takes the mode a
// new file would get. The writer's destructor, and SIGINT, SIGTERM or SIGHUP meanwhile,
// remove the spare.
// One writer per thread; writers on several threads may share a folder.
class AtomicWriter {
 public:
  AtomicWriter() = default;
  AtomicWriter(const AtomicWriter&) = delete;
  AtomicWriter& operator=(const AtomicWriter&) = delete;
  ~AtomicWriter();

  // Fails with kIoError naming `path`.
  Status Write(const std::string& path, std::initializer_list<std::string_view> parts);

 private:
  bool WriteOverSpare(const std::string& path,
                      const std::string& folder,
                      std::initializer_list<std::string_view> parts);
  void KeepSpare(std::string tmp, std::string folder);
  void ForgetSpare();  // no spare any more, the file left where it is
  void DropSpare();    // the spare unlinked

  std::string spare_;  // the kept file's path, "" when there is none
  std::string spare_folder_;
  int cleanup_slot_ = -1;
  unsigned new_file_mode_ = 0;  // what a newly created file got, umask applied (0: none made yet)
};

// One output written through a writer of its own: `bytes` to a temporary file beside
// `path`, swapped or renamed into place, the replaced file removed, so a crash or error
// never leaves a partial file. Fails with kIoError naming the path.
Status WriteFileAtomic(const std::string& path, const std::string& bytes);

// WriteFileAtomic of the concatenation of `parts`, without joining them in memory first
// (a .glb's binary chunk is most of the file). Through `writer` when one is given (a caller
// writing many files keeps one per thread, which reuses the files it replaces).
Status WriteFileAtomicParts(const std::string& path, std::initializer_list<std::string_view> parts,
                            AtomicWriter* writer = nullptr);

// Removes from `folder` the temporary files ("NAME.tmp-PID") that writers of processes no
// longer running left behind: a run killed with SIGKILL cannot remove its own. Files of
// running processes are left alone. Returns how many were removed.
size_t RemoveStaleTemporaries(const std::string& folder);

}  // namespace mocapfill
