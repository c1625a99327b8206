// SPDX-License-Identifier: LGPL-2.1-or-later
// A registry of plugins by name, as ASPECT's: each plugin (an indenter
// shape, an interaction law) registers itself from its own source file
// with VISCOSLIDE_REGISTER, so that adding one is one new file and no list
// of names is written anywhere else. The parameter file's Selection
// pattern, the entry's documentation and --print-parameters come from the
// registry.
#ifndef viscoslide_registry_h
#define viscoslide_registry_h

#include <viscoslide/io/input.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace viscoslide
{
  // Plugin: a struct with at least `std::string name, description;`.
  template <typename Plugin>
  class Registry
  {
  public:
    // Called by VISCOSLIDE_REGISTER during static initialisation. Two
    // plugins of one name are a programming error.
    static bool
    add(const Plugin &plugin)
    {
      auto &all = entries();
      if (std::any_of(all.begin(), all.end(), [&](const Plugin &p) {
            return p.name == plugin.name;
          }))
        throw std::logic_error("two plugins named '" + plugin.name + "'");
      all.push_back(plugin);
      std::sort(all.begin(), all.end(), [](const Plugin &a, const Plugin &b) {
        return a.name < b.name;
      });
      return true;
    }

    // The plugin called `name`; Parameters::ExcInvalidInput naming `entry`
    // and the registered names otherwise.
    static const Plugin &
    get(const std::string &name, const std::string &entry)
    {
      const auto &all = entries();
      return all[Parameters::find_choice(names(), name, entry)];
    }

    // The registered names, sorted.
    static std::vector<std::string>
    names()
    {
      std::vector<std::string> n;
      for (const auto &p : entries())
        n.push_back(p.name);
      return n;
    }

    // "a|b|c", for Patterns::Selection.
    static std::string
    pattern()
    {
      return Parameters::selection_pattern(names());
    }

    // "'a': description of a. 'b': ...", for an entry's documentation.
    static std::string
    documentation()
    {
      std::string text;
      for (const auto &p : entries())
        text += (text.empty() ? "'" : " '") + p.name + "': " + p.description;
      return text;
    }

  private:
    // A function-local static, so that registration from any translation
    // unit's static initialisation finds it constructed.
    static std::vector<Plugin> &
    entries()
    {
      static std::vector<Plugin> all;
      return all;
    }
  };
} // namespace viscoslide

#define VISCOSLIDE_REGISTRY_JOIN2(a, b) a##b
#define VISCOSLIDE_REGISTRY_JOIN(a, b) VISCOSLIDE_REGISTRY_JOIN2(a, b)

// VISCOSLIDE_REGISTER(PluginType, {name, description, ...}) at namespace
// scope of the plugin's source file.
#define VISCOSLIDE_REGISTER(Plugin, ...)                                       \
  namespace                                                                    \
  {                                                                            \
    const bool VISCOSLIDE_REGISTRY_JOIN(viscoslide_registered_, __COUNTER__) = \
      ::viscoslide::Registry<Plugin>::add(Plugin __VA_ARGS__);                 \
  }

#endif
