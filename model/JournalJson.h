#pragma once
// The journal (model/Journal.h) as a project file writes it: a state's "reached" entries, each a
// short array [step, kind, values...], and the gather drives they name in a table of their own
// (docs/project-format.md, "Journal").
#include "model/Journal.h"
#include "model/JsonFormat.h"

#include <QJsonArray>

#include <unordered_map>

namespace vf::model {

using DrivePtr = std::shared_ptr<const sim::TargetDrive>;

// The drives the entries name, each once (a drive is named by every step it feeds).
class DriveTable {
public:
    qint64 add(const DrivePtr& drive);
    QJsonArray toJson() const;

private:
    std::unordered_map<const sim::TargetDrive*, qint64> m_index;
    std::vector<DrivePtr> m_drives;
};

// `entries` with their steps as they are (counted from the state they were reached from).
QJsonArray journalToJson(const std::vector<JournalEntry>& entries, DriveTable& drives);

// Throws json::ReadError at the key path of what is wrong.
std::vector<DrivePtr> readDrives(const json::Field& field);
// Entries of a span of `steps` steps: each step in [0, steps], in order.
std::vector<JournalEntry> readJournal(const json::Field& field, std::int64_t steps, const std::vector<DrivePtr>& drives);

} // namespace vf::model
