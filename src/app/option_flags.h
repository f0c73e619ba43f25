// Command-line flags whose values are typed options (include/fastshade/options.h): the flag
// reads its text through the option's spelling, and a bad one is the usual InputError naming
// the flag.
#pragma once
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "fastshade/options.h"

namespace fastshade {

template <OptionValue T>
CLI::Option* add_option_flag(CLI::App* app, const std::string& flag, T& target, const std::string& help) {
  return app
      ->add_option_function<std::string>(
          flag, [&target, flag](const std::string& text) { target = parse_option<T>(text, flag); }, help)
      ->type_name("NAME");
}

// A list of them: comma-separated ("--isa scalar,avx2"), the flag given again replacing it.
template <OptionValue T>
CLI::Option* add_option_list_flag(CLI::App* app, const std::string& flag, std::vector<T>& target,
                                  const std::string& help) {
  return app
      ->add_option_function<std::vector<std::string>>(
          flag,
          [&target, flag](const std::vector<std::string>& texts) {
            target.clear();
            for (const std::string& text : texts) target.push_back(parse_option<T>(text, flag));
          },
          help)
      ->delimiter(',')
      ->type_name("NAME[,NAME...]");
}

}  // namespace fastshade
