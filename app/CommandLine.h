#pragma once
// The command line's conventions, shared by the program and each of its commands: a
// QCommandLineParser with -h/--help and --version, and errors in one line.
#include <QCommandLineParser>
#include <QString>

#include <optional>

namespace vf::app {

class CommandLine {
public:
    // `command`: how errors refer the user to the help ("vectorfluid render"). `usage`: the
    // synopsis that --help prints first (Qt's own usage line names the binary's full path and no
    // command).
    CommandLine(QString command, QString usage);

    QCommandLineParser& parser() { return m_parser; }
    // For a command that takes no options of its own: the one line any unknown option gets.
    void setRefusal(QString line) { m_refusal = std::move(line); }

    // Parses `arguments` (those after the program or command name). Returns an exit code when the
    // command has nothing left to do: 0 after printing --help or --version, 2 after printing one
    // line for an unknown option or a missing value. Otherwise the parser holds the values.
    std::optional<int> parse(const QStringList& arguments);

private:
    QString problem(const QStringList& arguments) const;

    QString m_command;
    QString m_usage;
    QString m_refusal;
    QCommandLineParser m_parser;
    QCommandLineOption m_help;
    QCommandLineOption m_version;
};

// Prints "vectorfluid: <line>" on stderr.
void printError(const QString& line);

} // namespace vf::app
