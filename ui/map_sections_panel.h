#pragma once
// The mapped tunnel as lists an inspector works down: its sections (extent, size, frames), the
// stations out of tolerance (with their deviation from the design), the stretches to rescan
// (whose width or height no frame measured), the diaphragm plates with their manholes and the
// compartments between them; first, the notes on the mapping that `map` prints (pose groups
// nothing checks, an IMU noisier than weighed).
// A click on a row asks for that station (the window shows the frame that sees it and cuts the
// cross-section there, as a click on the profile does); the profile's station selects the row.
#include <QWidget>
#include <string>
#include <vector>

#include "core/mapping/station_map.h"

class QLabel;
class QTreeWidget;
class QTreeWidgetItem;

namespace tunnelmap::ui {

class MapSectionsPanel : public QWidget {
  Q_OBJECT
 public:
  explicit MapSectionsPanel(QWidget* parent = nullptr);

  void set_map(const StationMap& map, const std::vector<std::string>& notes = {});
  void clear();
  // Selects the section containing `station_m` (or that out-of-tolerance station), no signal;
  // a selected row that stands for `station_m` stays selected.
  void select_station(double station_m);
  QTreeWidget* tree() const { return tree_; }
  int section_rows() const;
  int out_of_tolerance_rows() const;
  int rescan_rows() const;
  int note_rows() const;

 signals:
  void stationChosen(double station_m);

 private:
  void add_notes(const std::vector<std::string>& notes);
  void add_sections(const StationMap& map);
  void add_out_of_tolerance(const StationMap& map);
  void add_rescan(const StationMap& map);
  void add_diaphragms(const StationMap& map);
  void add_compartments(const StationMap& map);

  QLabel* summary_;
  QTreeWidget* tree_;
  QTreeWidgetItem* notes_ = nullptr;
  QTreeWidgetItem* sections_ = nullptr;
  QTreeWidgetItem* out_of_tolerance_ = nullptr;
  QTreeWidgetItem* rescan_ = nullptr;
  QTreeWidgetItem* diaphragms_ = nullptr;
  QTreeWidgetItem* compartments_ = nullptr;
};

}  // namespace tunnelmap::ui
