// Reads a scene with the installed engine and prints "<name>: <objects> objects,
// <plugins> plugins", or its diagnostics and exit status 1.
#include "scene_xml/scene_reader.h"

#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: scene_summary <scene.xml>\n");
    return 2;
  }
  const mhd::Result<mhd::SceneDescription> read = mhd::read_scene_file(argv[1]);
  if (!read.ok()) {
    std::fprintf(stderr, "%s\n", read.error_text().c_str());
    return 1;
  }
  std::printf("%s: %zu objects, %zu plugins\n", read->name.c_str(), read->objects.size(),
              read->plugins.size());
  return 0;
}
