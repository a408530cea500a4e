// SPDX-License-Identifier: Apache-2.0
#include "sculpt/cli/shell_completion.h"

#include "core/base/errors.h"

#include <CLI/CLI.hpp>

#include <sstream>
#include <vector>

namespace sculpt::cli {

namespace {

/// What a shell needs of an option: its names, whether it takes a value, its choices.
struct OptionSpec {
    std::vector<std::string> names;  ///< "--shape", "-o"
    std::string help;                ///< its description's first line
    bool takesValue = false;
    std::vector<std::string> choices;  ///< from CLI::IsMember, shown as TEXT:{a,b,c}
};

struct CommandSpec {
    std::string name, help;
    std::vector<OptionSpec> options;
};

std::string firstLine(const std::string& text) { return text.substr(0, text.find('\n')); }

std::vector<std::string> choicesOf(const std::string& typeName)
{
    std::vector<std::string> choices;
    const std::size_t open = typeName.find(":{"), close = typeName.rfind('}');
    if (open == std::string::npos || close == std::string::npos || close < open) return choices;
    std::istringstream list(typeName.substr(open + 2, close - open - 2));
    for (std::string choice; std::getline(list, choice, ',');) choices.push_back(choice);
    return choices;
}

std::vector<OptionSpec> optionsOf(const CLI::App& app)
{
    std::vector<OptionSpec> specs;
    for (const CLI::Option* option : app.get_options()) {
        if (!option->nonpositional() || option->get_group().empty()) continue;
        OptionSpec spec;
        for (const std::string& name : option->get_lnames()) spec.names.push_back("--" + name);
        for (const std::string& name : option->get_snames()) spec.names.push_back("-" + name);
        spec.help = firstLine(option->get_description());
        spec.takesValue = option->get_items_expected_min() > 0;
        spec.choices = choicesOf(option->get_type_name());
        specs.push_back(spec);
    }
    return specs;
}

std::vector<CommandSpec> commandsOf(const CLI::App& app)
{
    std::vector<CommandSpec> commands;
    for (const CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; }))
        commands.push_back({command->get_name(), firstLine(command->get_description()), optionsOf(*command)});
    return commands;
}

std::string joined(const std::vector<std::string>& words, const char* separator = " ")
{
    std::string text;
    for (const std::string& word : words) text += (text.empty() ? "" : separator) + word;
    return text;
}

/// Text inside single quotes for bash, zsh and fish alike.
std::string quoted(const std::string& text)
{
    std::string out = "'";
    for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
}

std::string bashScript(const CLI::App& app, const std::vector<CommandSpec>& commands)
{
    std::ostringstream s;
    std::vector<std::string> names;
    for (const CommandSpec& command : commands) names.push_back(command.name);
    for (const OptionSpec& option : optionsOf(app)) names.insert(names.end(), option.names.begin(), option.names.end());
    s << "# bash completion for sculpt (made by `sculpt --completion bash`)\n_sculpt()\n{\n"
      << "    local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]}\n"
      << "    if ((COMP_CWORD == 1)); then\n        COMPREPLY=($(compgen -W " << quoted(joined(names))
      << " -- \"$cur\"))\n        return\n    fi\n    local options=\n    case ${COMP_WORDS[1]} in\n";
    for (const CommandSpec& command : commands) {
        std::vector<std::string> all;
        for (const OptionSpec& option : command.options)
            all.insert(all.end(), option.names.begin(), option.names.end());
        s << "    " << command.name << ")\n        options=" << quoted(joined(all)) << "\n        case $prev in\n";
        for (const OptionSpec& option : command.options)
            if (!option.choices.empty())
                s << "        " << joined(option.names, "|") << ") COMPREPLY=($(compgen -W "
                  << quoted(joined(option.choices)) << " -- \"$cur\")); return ;;\n";
        s << "        esac ;;\n";
    }
    s << "    esac\n    if [[ $cur == -* ]]; then\n        COMPREPLY=($(compgen -W \"$options\" -- \"$cur\"))\n"
      << "    else\n        COMPREPLY=($(compgen -f -- \"$cur\"))\n    fi\n}\n"
      << "complete -o filenames -o bashdefault -F _sculpt sculpt\n";
    return s.str();
}

/// An _arguments spec's description: brackets are its syntax.
std::string zshText(const std::string& text)
{
    std::string out;
    for (const char c : text) {
        if (c == '[' || c == ']' || c == '\\') out += '\\';
        out += c;
    }
    return out;
}

std::string zshScript(const std::vector<CommandSpec>& commands)
{
    std::ostringstream s;
    s << "#compdef sculpt\n# zsh completion for sculpt (made by `sculpt --completion zsh`)\n_sculpt() {\n"
      << "    local -a commands\n    commands=(\n";
    for (const CommandSpec& command : commands) s << "        " << quoted(command.name + ":" + command.help) << "\n";
    s << "    )\n    if ((CURRENT == 2)); then\n        _describe command commands\n        return\n    fi\n"
      << "    case $words[2] in\n";
    for (const CommandSpec& command : commands) {
        s << "    " << command.name << ")\n        _arguments";
        for (const OptionSpec& option : command.options) {
            const std::string names =
                option.names.size() == 1 ? option.names.front() : "{" + joined(option.names, ",") + "}";
            std::string value;
            if (!option.choices.empty()) value = ":value:(" + joined(option.choices) + ")";
            else if (option.takesValue) value = ":value:_files";
            const std::string spec = "[" + zshText(option.help) + "]" + value;
            s << " \\\n            " << (option.names.size() == 1 ? quoted(names + spec) : names + quoted(spec));
        }
        s << " \\\n            '*:file:_files' ;;\n";
    }
    s << "    esac\n}\n_sculpt \"$@\"\n";
    return s.str();
}

std::string fishScript(const std::vector<CommandSpec>& commands)
{
    std::ostringstream s;
    s << "# fish completion for sculpt (made by `sculpt --completion fish`)\n";
    for (const CommandSpec& command : commands)
        s << "complete -c sculpt -f -n __fish_use_subcommand -a " << command.name << " -d " << quoted(command.help)
          << "\n";
    for (const CommandSpec& command : commands)
        for (const OptionSpec& option : command.options) {
            s << "complete -c sculpt -n " << quoted("__fish_seen_subcommand_from " + command.name);
            for (const std::string& name : option.names)
                s << (name.rfind("--", 0) == 0 ? " -l " + name.substr(2) : " -s " + name.substr(1));
            s << " -d " << quoted(option.help);
            if (!option.choices.empty()) s << " -x -a " << quoted(joined(option.choices));
            else if (option.takesValue) s << " -r -F";
            s << "\n";
        }
    return s.str();
}

}  // namespace

std::string completionScript(const CLI::App& app, const std::string& shell)
{
    const std::vector<CommandSpec> commands = commandsOf(app);
    if (shell == "bash") return bashScript(app, commands);
    if (shell == "zsh") return zshScript(commands);
    if (shell == "fish") return fishScript(commands);
    throw InputError("--completion: no completion for the shell '" + shell + "' (bash, zsh or fish)");
}

}  // namespace sculpt::cli
