// The built-in synthetic scenes, by name: one table row each ({name, summary, builder},
// SceneCatalogue.cpp), which cuetrack-synth --list and --help print as they are. Every
// scene is 640x480, 150 frames at 30 fps unless the caller changes its SceneSpec.
//
//   SceneSpec spec;
//   char err[512];
//   if (!makeScene("twin-crossing", &spec, err, sizeof err)) fail(err);  // lists the names
#pragma once

#include <cstddef>

#include "cuetrack/drivers/SceneSpec.hpp"

namespace cuetrack {

struct SceneEntry {
  const char* name;             // as in synth:NAME and --scene NAME
  const char* summary;          // one line for --help: what the scene tests
  void (*build)(SceneSpec& s);  // fills in the objects, background and model settings
};

int sceneCount();
const SceneEntry* sceneEntry(int i);  // nullptr when out of range
const char* sceneName(int i);         // nullptr when out of range

// Fills *out with the named scene; false for a name the table has not.
bool makeScene(const char* name, SceneSpec* out);
// The same, with one line in err for an unknown name:
// "unknown scene 'NAME' (scenes: moving, twin-crossing, ...)".
bool makeScene(const char* name, SceneSpec* out, char* err, size_t errLen);
// A source spec naming a scene ("synth:NAME[:FRAMES]", "still:...:NAME@...") names one the table
// has: false with the line "synth:NAME: unknown scene ..." in err otherwise, so that every
// tool refuses it as a bad command line (exit 2) before anything opens. True for any
// other spec (its reader judges it).
bool knownSceneSource(const char* spec, char* err, size_t errLen);
// The names, separated by `separator` (e.g. ", "), cut short to fit len.
void listSceneNames(const char* separator, char* out, size_t len);

}  // namespace cuetrack
