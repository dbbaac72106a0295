// mocapfill, the front end, is a static executable for start-up speed (main.cc), and a static
// executable cannot load the Assimp plug-in: the plug-in and libassimp would bring a second C
// library into the process. Its main hands every command line naming an Assimp input to
// mocapfill-full before anything is read. This definition, linked ahead of mocapfill_formats,
// stands in for the plug-in loader (formats/assimp/assimp_loader.cc), so that none of it is
// linked in, and says what happened should it ever be reached.
#include "formats/assimp/assimp_loader.h"

namespace mocapfill {

Result<Scene> ReadWithAssimpModule(const std::string& path, const ImportOptions&) {
  return Unsupported(path + ": Assimp formats are read by mocapfill-full, not by this front end");
}

}  // namespace mocapfill
