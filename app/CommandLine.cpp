#include "app/CommandLine.h"

#include "app/Commands.h"

#include <QTextStream>

namespace vf::app {

CommandLine::CommandLine(QString command, QString usage)
    : m_command(std::move(command))
    , m_usage(std::move(usage))
    , m_help({QStringLiteral("h"), QStringLiteral("help")}, QStringLiteral("Show this help and exit."))
    , m_version(QStringLiteral("version"), QStringLiteral("Show the version and exit."))
{
    // "-help" is one unknown option, not -h -e -l -p.
    m_parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    m_parser.addOption(m_help);
    m_parser.addOption(m_version);
}

std::optional<int> CommandLine::parse(const QStringList& arguments)
{
    if (!m_parser.parse(QStringList{QStringLiteral("vectorfluid")} + arguments)) {
        printError(problem(arguments));
        return BadInput;
    }
    if (m_parser.isSet(m_help)) {
        // Qt's text starts with its own usage line; ours replaces it.
        const QString text = m_parser.helpText();
        QTextStream(stdout) << m_usage << text.mid(text.indexOf(u'\n') + 1);
        return Done;
    }
    if (m_parser.isSet(m_version)) {
        QTextStream(stdout) << "vectorfluid " VF_VERSION "\n";
        return Done;
    }
    return std::nullopt;
}

// The parser's own messages ("Unknown option 'x'.") in this program's words, which its tests and
// scripts match.
QString CommandLine::problem(const QStringList& arguments) const
{
    if (!m_refusal.isEmpty())
        return m_refusal;
    if (const QStringList unknown = m_parser.unknownOptionNames(); !unknown.isEmpty())
        return QStringLiteral("unknown option %1%2 (see %3 --help)")
            .arg(unknown.front().size() == 1 ? "-" : "--", unknown.front(), m_command);
    // The other failure that matters: an option that takes a value came last, without one.
    if (!arguments.isEmpty() && arguments.back().startsWith(u'-'))
        return QStringLiteral("%1 needs a value").arg(arguments.back());
    return m_parser.errorText();
}

void printError(const QString& line)
{
    QTextStream(stderr) << "vectorfluid: " << line << '\n';
}

} // namespace vf::app
