#pragma once
// Running the external readers the render tests check files with (xmllint, rsvg-convert, qpdf,
// Ghostscript, ffprobe, ...), and skipping a test when one is not installed.
#include <QProcess>
#include <QStandardPaths>
#include <QString>
#include <QStringList>

struct Run {
    int exitCode = -1;
    QByteArray output;
};

inline Run run(const QString& program, const QStringList& arguments)
{
    QProcess process;
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(program, arguments);
    // Inkscape takes about a minute over the largest file on a busy two-core machine.
    if (!process.waitForFinished(300000) || process.exitStatus() != QProcess::NormalExit)
        return {-1, process.readAll()};
    return {process.exitCode(), process.readAll()};
}

#define REQUIRE_TOOL(variable, name)                                                                     \
    const QString variable = QStandardPaths::findExecutable(QStringLiteral(name));                       \
    if (variable.isEmpty())                                                                              \
        QSKIP(name " is not installed");
