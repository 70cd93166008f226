// The progress line of `vectorfluid render` (app/RenderProgress.h): on a terminal a run past its
// quiet start shows "step S of N, V vertices, about T left", rewritten in place and cleared at
// the end; with stdout and stderr on pipes the same run prints nothing but its one real line.
// Both runs are too long to finish and are interrupted once past the quiet start.
#include "CliRun.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <csignal>
#include <fcntl.h>
#include <pty.h>
#include <unistd.h>

using namespace vf;
using namespace vf::test;

namespace {

const QString kStirred = QStringLiteral(VF_TEST_DATA "/scenes/stirred.vfscene");
// RenderProgress's quiet start, with a margin.
constexpr qint64 kPastQuietStartMs = 3500;
constexpr int kEvery = 10;

QString frame(const QString& dir, qint64 step)
{
    return QDir(dir).filePath(QStringLiteral("frame-%1.svg").arg(step, 9, 10, QLatin1Char('0')));
}

// A pseudo-terminal for a child's stdout and stderr; what the child writes is read from `master`.
struct Terminal {
    int master = -1;
    int slave = -1;
    ~Terminal()
    {
        for (int fd : {master, slave}) {
            if (fd >= 0)
                ::close(fd);
        }
    }
    // Appends what has come so far.
    void read(QByteArray& into) const
    {
        char buffer[4096];
        ssize_t n;
        while ((n = ::read(master, buffer, sizeof buffer)) > 0)
            into.append(buffer, n);
    }
};

// Runs a render of 100,000,000 steps (frames every kEvery steps in `frames`), on `terminal` or on
// pipes, and interrupts it once its progress line could show: frame 0 is written after the line's
// clock starts, so kPastQuietStartMs after it, and two frames later, the run has been updating its
// progress past the quiet start. `terminalText` gets what the terminal showed.
CliResult runAndInterrupt(const QString& frames, Terminal* terminal, QByteArray* terminalText)
{
    QProcess process;
    if (terminal) {
        const int slave = terminal->slave;
        process.setChildProcessModifier([slave] {
            ::dup2(slave, STDOUT_FILENO);
            ::dup2(slave, STDERR_FILENO);
        });
    }
    process.start(kBinary, {QStringLiteral("render"), kStirred, QStringLiteral("--backend"), QStringLiteral("reference"),
                            QStringLiteral("--steps"), QStringLiteral("100000000"), QStringLiteral("--frames"), frames,
                            QStringLiteral("--every"), QString::number(kEvery)});
    const auto pump = [&] {
        if (terminal)
            terminal->read(*terminalText);
    };
    const auto written = [&](qint64 step) {
        return QTest::qWaitFor([&] { pump(); return QFileInfo::exists(frame(frames, step)); }, 60000);
    };
    if (!process.waitForStarted() || !written(0))
        return {};
    QElapsedTimer sinceFrame0;
    sinceFrame0.start();
    if (!QTest::qWaitFor([&] { pump(); return sinceFrame0.elapsed() > kPastQuietStartMs; }, 60000))
        return {};
    qint64 last = 0;
    while (QFileInfo::exists(frame(frames, last + kEvery)))
        last += kEvery;
    if (!written(last + 2 * kEvery))
        return {};
    ::kill(pid_t(process.processId()), SIGINT);
    if (!QTest::qWaitFor([&] { pump(); return process.state() == QProcess::NotRunning; }, 60000))
        return {};
    pump();
    return {process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1, process.readAllStandardOutput(),
            process.readAllStandardError()};
}

} // namespace

class TestCliProgress : public QObject {
    Q_OBJECT

private slots:
    void init()
    {
        m_dir = std::make_unique<QTemporaryDir>();
        QVERIFY(m_dir->isValid());
    }

    void terminalShowsStepsVerticesAndTimeLeft()
    {
        Terminal terminal;
        QVERIFY(::openpty(&terminal.master, &terminal.slave, nullptr, nullptr, nullptr) == 0);
        QVERIFY(::fcntl(terminal.master, F_SETFL, O_NONBLOCK) == 0);
        QByteArray shown;
        const CliResult r = runAndInterrupt(m_dir->filePath(QStringLiteral("frames")), &terminal, &shown);
        QCOMPARE(r.exitCode, 130);

        const QString text = QString::fromUtf8(shown);
        const QRegularExpression line(QStringLiteral("\\rstep (\\d+) of 100000000, (\\d+) vertices, about [\\d.]+ (s|min|h) left\\x1b\\[K"));
        const QRegularExpressionMatch first = line.match(text);
        QVERIFY2(first.hasMatch(), qPrintable(text.toUtf8().toPercentEncoding(" ,.")));
        QVERIFY(first.captured(1).toLongLong() > 0);
        QVERIFY(first.captured(2).toLongLong() > 0);
        // At the end the line is cleared, and the run's one real line follows on its own.
        const qsizetype cleared = text.lastIndexOf(QStringLiteral("\r\x1b[K"));
        QVERIFY(cleared > first.capturedStart());
        const QString after = text.mid(cleared + 4);
        QVERIFY2(after.startsWith(QStringLiteral("vectorfluid: ")) && after.contains(QStringLiteral("interrupted at step"))
                     && after.count(u'\n') == 1 && after.endsWith(u'\n'),
                 qPrintable(after));
    }

    void pipesShowNoProgress()
    {
        const CliResult r = runAndInterrupt(m_dir->filePath(QStringLiteral("frames")), nullptr, nullptr);
        CHECK_OK(checkOneLineError(r, {kStirred, QStringLiteral("interrupted at step")}, 130));
        QVERIFY2(r.out.isEmpty(), qPrintable(describe(r)));
        QVERIFY2(!r.err.contains('\r') && !r.err.contains("\x1b"), qPrintable(describe(r)));
    }

private:
    std::unique_ptr<QTemporaryDir> m_dir;
};

QTEST_GUILESS_MAIN(TestCliProgress)
#include "tst_cli_progress.moc"
