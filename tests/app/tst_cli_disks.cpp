// `vectorfluid render` onto real file systems that run out of room (README, "The command line"):
// an ext4 image mounted from a loop file and filled, and an ext2 image whose own backing file
// cannot grow, so every write() succeeds and the failure comes only when the data is written
// back. Each run says "disk full" in one line, exits 2, leaves no part of its outputs and the
// previous file as it was. Mounting needs root (CI runs as root); elsewhere the tests skip.
#include "../TestFiles.h"
#include "CliRun.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <unistd.h>

using namespace vf;
using namespace vf::test;

namespace {

const QString kStirred = QStringLiteral(VF_TEST_DATA "/scenes/stirred.vfscene");
const QByteArray kKeepSvg = "<svg>the previous picture</svg>\n";

QStringList entries(const QString& dir)
{
    return QDir(dir).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden);
}

// Runs a tool; an empty string, or one line of why it failed.
QString runTool(const QString& program, const QStringList& arguments)
{
    QProcess process;
    process.start(program, arguments);
    if (!process.waitForFinished(60000) || process.exitStatus() != QProcess::NormalExit || process.exitCode() != 0)
        return QStringLiteral("%1 %2: %3").arg(program, arguments.join(u' '),
                                               QString::fromUtf8(process.readAllStandardError()).simplified());
    return {};
}

// A file system mounted for one test, unmounted when the object goes, whatever the test did.
class Mount {
public:
    Mount() = default;
    Mount(const Mount&) = delete;
    Mount& operator=(const Mount&) = delete;
    ~Mount()
    {
        if (!m_point.isEmpty())
            runTool(QStringLiteral("umount"), {m_point});
    }

    // `mount OPTIONS... SOURCE POINT`; an empty string, or why not.
    QString mount(const QStringList& options, const QString& source, const QString& point)
    {
        if (!QDir().mkpath(point))
            return QStringLiteral("cannot create %1").arg(point);
        const QString error = runTool(QStringLiteral("mount"), options + QStringList{source, point});
        if (error.isEmpty())
            m_point = point;
        return error;
    }

private:
    QString m_point;
};

// An image file of `size` with a fresh file system made by `mkfs` (mkfs.ext4, mkfs.ext2).
QString makeImage(const QString& image, const QString& size, const QString& mkfs)
{
    if (QString error = runTool(QStringLiteral("truncate"), {QStringLiteral("-s"), size, image}); !error.isEmpty())
        return error;
    return runTool(mkfs, {QStringLiteral("-q"), QStringLiteral("-F"), image});
}

// Writes `file` until its file system refuses more (ENOSPC), then gives back `leave` bytes.
bool fill(const QString& file, qint64 leave)
{
    QFile filler(file);
    if (!filler.open(QIODevice::WriteOnly | QIODevice::Unbuffered))
        return false;
    const QByteArray block(64 * 1024, 'x');
    while (filler.write(block) > 0) {}
    return filler.resize(std::max<qint64>(0, filler.size() - leave));
}

// Writes `file` and waits until it is on the disk, so that it is no longer the page cache's.
bool writeSynced(const QString& file, const QByteArray& content)
{
    QFile out(file);
    return out.open(QIODevice::WriteOnly) && out.write(content) == content.size() && out.flush()
           && ::fsync(out.handle()) == 0;
}

CliResult renderInto(const QString& dir)
{
    return runCli({QStringLiteral("render"), kStirred, QStringLiteral("--backend"), QStringLiteral("reference"),
                   QStringLiteral("--steps"), QStringLiteral("3"), QStringLiteral("--polyline"), QStringLiteral("--out"),
                   QDir(dir).filePath(QStringLiteral("keep.svg")), QStringLiteral("--out"),
                   QDir(dir).filePath(QStringLiteral("x.png")), QStringLiteral("--dpi"), QStringLiteral("600")});
}

} // namespace

class TestCliDisks : public QObject {
    Q_OBJECT

private slots:
    void init()
    {
        if (geteuid() != 0)
            QSKIP("mounting a file system needs root; tst_cli_faults covers failed writes with ulimit -f");
        m_dir = std::make_unique<QTemporaryDir>();
        QVERIFY(m_dir->isValid());
    }

    // A full ext4 disk, and one with 16 KB left, which the outputs fill part-way.
    void fullLoopDiskSaysDiskFull_data()
    {
        QTest::addColumn<qint64>("leave");
        QTest::newRow("full") << qint64(0);
        QTest::newRow("16 KB left") << qint64(16 * 1024);
    }
    void fullLoopDiskSaysDiskFull()
    {
        QFETCH(qint64, leave);
        const QString image = m_dir->filePath(QStringLiteral("disk.img"));
        const QString disk = m_dir->filePath(QStringLiteral("disk"));
        CHECK_OK(makeImage(image, QStringLiteral("4M"), QStringLiteral("mkfs.ext4")));
        Mount mount;
        if (const QString error = mount.mount({QStringLiteral("-o"), QStringLiteral("loop")}, image, disk); !error.isEmpty())
            QSKIP(qPrintable(QStringLiteral("cannot mount a loop file here: %1").arg(error)));
        QVERIFY(writeSynced(QDir(disk).filePath(QStringLiteral("keep.svg")), kKeepSvg));
        QVERIFY(fill(QDir(disk).filePath(QStringLiteral("filler")), leave));

        const CliResult r = renderInto(disk);
        CHECK_OK(checkOneLineError(r, {disk, QStringLiteral("disk full")}));
        QCOMPARE(entries(disk), (QStringList{QStringLiteral("filler"), QStringLiteral("keep.svg"), QStringLiteral("lost+found")}));
        QCOMPARE(readAll(QDir(disk).filePath(QStringLiteral("keep.svg"))), kKeepSvg);
    }

    // A disk that is full underneath its file system, as a thin-provisioned or network disk can
    // be: an ext2 image on a tmpfs that is then filled. Writes land in the page cache and succeed;
    // only fsync finds that the data cannot reach the image (the loop device reports ENOSPC).
    // ext2: without a journal, mkfs and mount write little into the image.
    void diskFullAtWriteBackSaysDiskFull()
    {
        const QString tray = m_dir->filePath(QStringLiteral("tray"));
        const QString disk = m_dir->filePath(QStringLiteral("disk"));
        Mount trayMount;
        if (const QString error = trayMount.mount({QStringLiteral("-t"), QStringLiteral("tmpfs"), QStringLiteral("-o"),
                                                   QStringLiteral("size=1m")},
                                                  QStringLiteral("tmpfs"), tray);
            !error.isEmpty())
            QSKIP(qPrintable(QStringLiteral("cannot mount a tmpfs here: %1").arg(error)));
        const QString image = QDir(tray).filePath(QStringLiteral("disk.img"));
        CHECK_OK(makeImage(image, QStringLiteral("8M"), QStringLiteral("mkfs.ext2")));
        Mount diskMount;
        if (const QString error = diskMount.mount({QStringLiteral("-o"), QStringLiteral("loop")}, image, disk); !error.isEmpty())
            QSKIP(qPrintable(QStringLiteral("cannot mount a loop file here: %1").arg(error)));
        QVERIFY(writeSynced(QDir(disk).filePath(QStringLiteral("keep.svg")), kKeepSvg));
        QVERIFY(fill(QDir(tray).filePath(QStringLiteral("filler")), 0));

        const CliResult r = renderInto(disk);
        CHECK_OK(checkOneLineError(r, {disk, QStringLiteral("disk full")}));
        QCOMPARE(entries(disk), (QStringList{QStringLiteral("keep.svg"), QStringLiteral("lost+found")}));
        QCOMPARE(readAll(QDir(disk).filePath(QStringLiteral("keep.svg"))), kKeepSvg);
    }

private:
    std::unique_ptr<QTemporaryDir> m_dir;
};

QTEST_GUILESS_MAIN(TestCliDisks)
#include "tst_cli_disks.moc"
