#pragma once
// Running the real `vectorfluid` binary (VF_BINARY) in the command-line tests, and the one-line
// error contract they check.
#include <QByteArray>
#include <QProcess>
#include <QString>
#include <QStringList>
#include <QtTest>

namespace vf::test {

const QString kBinary = QStringLiteral(VF_BINARY);

struct CliResult {
    int exitCode = -1;  // -1: crashed or hung
    QByteArray out;
    QByteArray err;
};

inline CliResult runProgram(const QString& program, const QStringList& arguments)
{
    QProcess process;
    process.start(program, arguments);
    const bool finished = process.waitForFinished(60000);
    CliResult result{-1, process.readAllStandardOutput(), process.readAllStandardError()};
    if (finished && process.exitStatus() == QProcess::NormalExit)
        result.exitCode = process.exitCode();
    return result;
}

inline CliResult runCli(const QStringList& arguments) { return runProgram(kBinary, arguments); }

inline QString describe(const CliResult& r)
{
    return QStringLiteral("exit %1, stdout [%2], stderr [%3]")
        .arg(r.exitCode)
        .arg(QString::fromUtf8(r.out), QString::fromUtf8(r.err));
}

// Exit 2, nothing on stdout, exactly one line on stderr containing every one of `needles`.
inline QString checkOneLineError(const CliResult& r, const QStringList& needles, int exitCode = 2)
{
    const QString err = QString::fromUtf8(r.err);
    if (r.exitCode != exitCode)
        return QStringLiteral("expected exit %1: %2").arg(exitCode).arg(describe(r));
    if (exitCode == 2 && !r.out.isEmpty())
        return QStringLiteral("stdout is not empty: ") + describe(r);
    if (r.err.count('\n') != 1 || !r.err.endsWith('\n'))
        return QStringLiteral("stderr is not exactly one line: ") + describe(r);
    for (const QString& needle : needles) {
        if (!err.contains(needle))
            return QStringLiteral("stderr lacks '%1': %2").arg(needle, describe(r));
    }
    return {};
}

} // namespace vf::test

#define CHECK_OK(expression)                                                                             \
    do {                                                                                                 \
        const QString problem_ = (expression);                                                           \
        QVERIFY2(problem_.isEmpty(), qPrintable(problem_));                                              \
    } while (false)

