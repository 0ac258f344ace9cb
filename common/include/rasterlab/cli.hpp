// The programs' command lines: CLI11 behind a small interface compiled once
// (common/src/cli.cpp), so that a program's main does not compile CLI11 again
// (it cost every main.cpp about 6 s of a release build). The names are
// CLI11's own (add_option, add_flag, check, capture_default_str, count), the
// parsing, the messages and --help are CLI11's; the options every lesson
// program shares are declared once below, so that every program spells them,
// checks them and documents them the same way.
//
//   rl::CommandLine app{"Lesson 02, triangles"};
//   rl::ImageOptions image_options{"02_triangles.tga"};  // -o, --width, --height
//   rl::add_image_options(app, image_options);
//   rl::add_method_option(app, "--raster", method, triangles::kRasterMethods, "Rasterizer");
//   rl::add_light_option(app, light);  // then rl::check_direction("--light", light)
//   app.add_option("--near", near)->check(rl::positive_number());
//   return app.run(argc, argv, "02_triangles", [&] {  // --help or a refused option: not run
//       rl::check_image_output(image_options.output);  // a throw: "02_triangles: error: ..."
//       return 0;
//   });
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "rasterlab/direction.hpp"
#include "rasterlab/named_enum.hpp"

namespace CLI {
class App;
class Option;
class Validator;
}  // namespace CLI

namespace rl {

// A check of an option's text: CLI11's validator, made in cli.cpp.
class Check {
  public:
    explicit Check(std::shared_ptr<const CLI::Validator> validator);
    const CLI::Validator& validator() const { return *validator_; }

  private:
    std::shared_ptr<const CLI::Validator> validator_;
};

// A whole number or a number in [low, high] (CLI::Range): "Value 0 not in range 1 to 16384".
Check range(int low, int high);
Check range(double low, double high);
// One of the listed values (CLI::IsMember).
Check one_of(std::vector<std::string> values);
Check one_of(std::vector<int> values);

// A finite number in [low, high], by default the range of a float (1e300
// would become infinity in one). CLI11 names the option in its message
// ("--far: 'inf' is not a finite number"). Every float option goes through
// it: NaN and infinity pass CLI11's own range checks, and a NaN light
// direction quietly drew a black image.
Check finite_number(double low = -std::numeric_limits<float>::max(),
                    double high = std::numeric_limits<float>::max());
// A number that must be greater than zero (a distance, a near plane).
Check positive_number();

// Thrown from an option's each() callback to refuse a value; the parse
// reports it as CLI11 reports a refused value, after the option's name.
struct OptionError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// One option of a command line (a CLI::Option); the calls chain as in CLI11.
class Option {
  public:
    explicit Option(CLI::Option* option) : option_(option) {}
    Option* check(const Check& check);
    // A check written in place: returns "" to accept the text, else why not.
    Option* check(std::function<std::string(const std::string&)> test);
    Option* capture_default_str();
    Option* default_str(const std::string& text);
    Option* expected(int values);
    Option* required();
    Option* excludes(Option* other);
    // Called with each value given, after the checks (an OptionError refuses it).
    Option* each(std::function<void(const std::string&)> callback);
    // How many times the option was given.
    std::size_t count() const;

  private:
    friend class CommandLine;
    CLI::Option* option_;
};

// A program's command line (a CLI::App), or one of its subcommands.
class CommandLine {
  public:
    explicit CommandLine(const std::string& description);
    ~CommandLine();
    CommandLine(const CommandLine&) = delete;
    CommandLine& operator=(const CommandLine&) = delete;

    // An option that stores its value in `value`: int, unsigned, float,
    // double, std::string, or a vector of float, int or std::string.
    template <class T>
    Option* add_option(const std::string& name, T& value, const std::string& help = "");
    // An option whose text is handed to `set` once parsed.
    Option* add_option_function(const std::string& name,
                                std::function<void(const std::string&)> set,
                                const std::string& help);
    Option* add_flag(const std::string& name, bool& value, const std::string& help = "");
    Option* get_option(const std::string& name);
    void remove_option(Option* option);
    std::size_t count(const std::string& name) const;
    void footer(const std::string& text);
    CommandLine* add_subcommand(const std::string& name, const std::string& description);
    // Whether this subcommand was given.
    bool parsed() const;

    // Parses the arguments; on --help or a refused option, prints what CLI11
    // prints and returns the exit code for main to return.
    std::optional<int> parse(int argc, char** argv);

    // A program's main in one call: parses the arguments (--help and a
    // refused option end here, as parse() says), then runs `body` under
    // rl::guarded_main (main_guard.hpp) and returns its exit code.
    int run(int argc, char** argv, const char* program, const std::function<int()>& body);

  private:
    explicit CommandLine(CLI::App* subcommand);
    Option* wrap(CLI::Option* option);

    std::unique_ptr<CLI::App> owned_;
    CLI::App* app_;
    std::vector<std::unique_ptr<Option>> options_;
    std::vector<std::unique_ptr<CommandLine>> subcommands_;
};

extern template Option* CommandLine::add_option(const std::string&, int&, const std::string&);
extern template Option* CommandLine::add_option(const std::string&, unsigned&, const std::string&);
extern template Option* CommandLine::add_option(const std::string&, float&, const std::string&);
extern template Option* CommandLine::add_option(const std::string&, double&, const std::string&);
extern template Option* CommandLine::add_option(const std::string&, std::string&,
                                                const std::string&);
extern template Option* CommandLine::add_option(const std::string&, std::vector<float>&,
                                                const std::string&);
extern template Option* CommandLine::add_option(const std::string&, std::vector<int>&,
                                                const std::string&);
extern template Option* CommandLine::add_option(const std::string&, std::vector<std::string>&,
                                                const std::string&);

struct ImageOptions {
    std::string output;
    int width = 800;
    int height = 800;
};

// --light X Y Z: the direction towards the light, three finite numbers;
// check_direction() refuses 0 0 0 once parsing is done.
void add_light_option(CommandLine& app, std::vector<float>& light);

// -o/--output, --width, --height (1 to 16384).
void add_image_options(CommandLine& app, ImageOptions& options);

// -m/--model: an OBJ file; the default is one of the project's own.
void add_model_option(CommandLine& app, std::string& model);

// An option choosing one value of a method enum by its name.
template <class E, std::size_t N>
Option* add_method_option(CommandLine& app, const std::string& flag, E& value,
                          const std::array<E, N>& all, const std::string& what) {
    std::vector<std::string> names;
    for (E e : all) names.push_back(name(e));
    return app
        .add_option_function(
            flag, [&value, all](const std::string& text) { value = *from_name(text, all); },
            what + ": " + names_of(all))
        ->check(one_of(names))
        ->default_str(name(value));
}

}  // namespace rl
