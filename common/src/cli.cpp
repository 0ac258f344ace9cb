// CLI11, compiled once for every program (rasterlab/cli.hpp says why).
#include "rasterlab/cli.hpp"

#include "rasterlab/main_guard.hpp"

#include <CLI/CLI.hpp>

#include <charconv>
#include <cmath>

namespace rl {

Check::Check(std::shared_ptr<const CLI::Validator> validator) : validator_(std::move(validator)) {}

namespace {

Check make_check(CLI::Validator validator) {
    return Check(std::make_shared<const CLI::Validator>(std::move(validator)));
}

}  // namespace

Check range(int low, int high) {
    return make_check(CLI::Range(low, high));
}

Check range(double low, double high) {
    return make_check(CLI::Range(low, high));
}

Check one_of(std::vector<std::string> values) {
    return make_check(CLI::IsMember(std::move(values)));
}

Check one_of(std::vector<int> values) {
    return make_check(CLI::IsMember(std::move(values)));
}

Check finite_number(double low, double high) {
    return make_check(CLI::Validator(
        [low, high](std::string& text) -> std::string {
            double value = 0;
            const char* end = text.data() + text.size();
            const auto [stop, error] = std::from_chars(text.data(), end, value);
            if (error == std::errc::result_out_of_range) return "'" + text + "' is out of range";
            if (error != std::errc{} || stop != end) return "'" + text + "' is not a number";
            if (!std::isfinite(value)) return "'" + text + "' is not a finite number";
            if (value < low || value > high)
                return "'" + text + "' is outside [" + std::to_string(low) + ", " +
                       std::to_string(high) + "]";
            return {};
        },
        "FINITE"));
}

Check positive_number() {
    return finite_number(std::numeric_limits<double>::denorm_min());
}

Option* Option::check(const Check& check) {
    option_->check(check.validator());
    return this;
}

Option* Option::check(std::function<std::string(const std::string&)> test) {
    option_->check(std::move(test));
    return this;
}

Option* Option::capture_default_str() {
    option_->capture_default_str();
    return this;
}

Option* Option::default_str(const std::string& text) {
    option_->default_str(text);
    return this;
}

Option* Option::expected(int values) {
    option_->expected(values);
    return this;
}

Option* Option::required() {
    option_->required();
    return this;
}

Option* Option::excludes(Option* other) {
    option_->excludes(other->option_);
    return this;
}

Option* Option::each(std::function<void(const std::string&)> callback) {
    // CLI11 puts the option's name before the message itself.
    option_->each([callback = std::move(callback)](const std::string& text) {
        try {
            callback(text);
        } catch (const OptionError& error) {
            throw CLI::ValidationError(error.what());
        }
    });
    return this;
}

std::size_t Option::count() const {
    return option_->count();
}

CommandLine::CommandLine(const std::string& description)
    : owned_(std::make_unique<CLI::App>(description)), app_(owned_.get()) {}

CommandLine::CommandLine(CLI::App* subcommand) : app_(subcommand) {}

CommandLine::~CommandLine() = default;

Option* CommandLine::wrap(CLI::Option* option) {
    if (option == nullptr) return nullptr;
    for (const std::unique_ptr<Option>& known : options_)
        if (known->option_ == option) return known.get();
    options_.push_back(std::make_unique<Option>(option));
    return options_.back().get();
}

template <class T>
Option* CommandLine::add_option(const std::string& name, T& value, const std::string& help) {
    return wrap(app_->add_option(name, value, help));
}

template Option* CommandLine::add_option(const std::string&, int&, const std::string&);
template Option* CommandLine::add_option(const std::string&, unsigned&, const std::string&);
template Option* CommandLine::add_option(const std::string&, float&, const std::string&);
template Option* CommandLine::add_option(const std::string&, double&, const std::string&);
template Option* CommandLine::add_option(const std::string&, std::string&, const std::string&);
template Option* CommandLine::add_option(const std::string&, std::vector<float>&,
                                         const std::string&);
template Option* CommandLine::add_option(const std::string&, std::vector<int>&, const std::string&);
template Option* CommandLine::add_option(const std::string&, std::vector<std::string>&,
                                         const std::string&);

Option* CommandLine::add_option_function(const std::string& name,
                                         std::function<void(const std::string&)> set,
                                         const std::string& help) {
    return wrap(app_->add_option_function<std::string>(name, std::move(set), help));
}

Option* CommandLine::add_flag(const std::string& name, bool& value, const std::string& help) {
    return wrap(app_->add_flag(name, value, help));
}

Option* CommandLine::get_option(const std::string& name) {
    return wrap(app_->get_option(name));
}

void CommandLine::remove_option(Option* option) {
    app_->remove_option(option->option_);
    std::erase_if(options_,
                  [option](const std::unique_ptr<Option>& known) { return known.get() == option; });
}

std::size_t CommandLine::count(const std::string& name) const {
    return app_->count(name);
}

void CommandLine::footer(const std::string& text) {
    app_->footer(text);
}

CommandLine* CommandLine::add_subcommand(const std::string& name, const std::string& description) {
    subcommands_.push_back(
        std::unique_ptr<CommandLine>(new CommandLine(app_->add_subcommand(name, description))));
    return subcommands_.back().get();
}

bool CommandLine::parsed() const {
    return app_->parsed();
}

std::optional<int> CommandLine::parse(int argc, char** argv) {
    try {
        app_->parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        return app_->exit(error);
    }
    return std::nullopt;
}

int CommandLine::run(int argc, char** argv, const char* program, const std::function<int()>& body) {
    if (const std::optional<int> exit = parse(argc, argv)) return *exit;
    return guarded_main(program, body);
}

void add_light_option(CommandLine& app, std::vector<float>& light) {
    app.add_option("--light", light, "Direction towards the light, x y z")
        ->expected(3)
        ->check(finite_number())
        ->capture_default_str();
}

void add_image_options(CommandLine& app, ImageOptions& options) {
    app.add_option("-o,--output", options.output, "Image to write (.tga or .png)")
        ->capture_default_str();
    app.add_option("--width", options.width, "Image width in pixels")
        ->capture_default_str()
        ->check(range(1, 16384));
    app.add_option("--height", options.height, "Image height in pixels")
        ->capture_default_str()
        ->check(range(1, 16384));
}

void add_model_option(CommandLine& app, std::string& model) {
    app.add_option("-m,--model", model, "OBJ file to draw")->capture_default_str();
}

}  // namespace rl
