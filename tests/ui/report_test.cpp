// The PDF inspection report, written headless (offscreen Qt platform, no DISPLAY) and read back
// the way a person or a script would: pdftotext for the words and numbers, pdftoppm for the
// pixels of page 1.
#include <gtest/gtest.h>

#include <QColor>
#include <QImage>
#include <QPainter>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "core/util/error.h"
#include "tests/ui/fresh_dir.h"
#include "tests/ui/report_test_map.h"
#include "ui/report/inspection_report.h"

namespace tunnelmap {
namespace {

namespace fs = std::filesystem;

bool have_tool(const char* tool) {
  return std::system((std::string("command -v ") + tool + " > /dev/null 2>&1").c_str()) == 0;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Text of pages first..last (all when 0), in reading layout.
std::string pdf_text(const std::string& pdf, int first = 0, int last = 0) {
  const std::string txt = pdf + ".txt";
  std::string cmd = "pdftotext -layout";
  if (first > 0) cmd += " -f " + std::to_string(first) + " -l " + std::to_string(last);
  cmd += " '" + pdf + "' '" + txt + "'";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  return read_file(txt);
}

int pdf_pages(const std::string& pdf) {
  const std::string info = pdf + ".info";
  EXPECT_EQ(std::system(("pdfinfo '" + pdf + "' > '" + info + "'").c_str()), 0);
  const std::string text = read_file(info);
  const auto at = text.find("Pages:");
  return at == std::string::npos ? 0 : std::atoi(text.c_str() + at + 6);
}

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

// A stand-in for the rendered map image: a dark background with a coloured box.
std::string write_fake_map_png(const std::string& dir) {
  QImage img(800, 500, QImage::Format_RGB888);
  img.fill(QColor(31, 31, 36));
  QPainter p(&img);
  p.fillRect(QRect(200, 120, 400, 260), QColor(220, 30, 30));
  p.fillRect(QRect(200, 120, 400, 20), QColor(30, 60, 230));
  p.end();
  const std::string path = dir + "/map.png";
  img.save(QString::fromStdString(path));
  return path;
}

InspectionReportInput report_input(const StationMap& map, const std::string& image) {
  InspectionReportInput in;
  in.input = "/data/girder-7/dataset.json";
  in.created = "2024-05-14 09:30";
  in.params = {{"grow.angle_deg", 4.0}, {"grow.distance_m", 0.02}, {"cloud.max_range_m", 5.0},
               {"normals.smoothing_px", 10}, {"map.station_step_m", 0.1}, {"tunnel.zone_gap_m", 0.01},
               {"outliers.bins", 20}};
  in.map = &map;
  in.map_image_png = image;
  if (image.empty()) in.map_image_note = "tunnelmap-render was not found next to tunnelmap-cli";
  return in;
}

// Every word of every page inside the page margins (16 mm left and right, 14 mm top, 10 mm
// bottom), as pdftotext -bbox reports them: nothing runs off the page.
void expect_words_inside_margins(const std::string& pdf) {
  const std::string html = pdf + ".bbox.html";
  ASSERT_EQ(std::system(("pdftotext -bbox '" + pdf + "' '" + html + "'").c_str()), 0);
  const std::string text = read_file(html);
  const double pt_per_mm = 72.0 / 25.4, slack = 0.5;
  const double left = 16 * pt_per_mm - slack, right = 595.28 - 16 * pt_per_mm + slack;
  const double top = 14 * pt_per_mm - slack, bottom = 841.89 - 10 * pt_per_mm + slack;
  const std::regex word(R"re(<word xMin="([-0-9.]+)" yMin="([-0-9.]+)" xMax="([-0-9.]+)" yMax="([-0-9.]+)">([^<]*)</word>)re");
  int words = 0;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), word); it != std::sregex_iterator(); ++it) {
    const auto& m = *it;
    ++words;
    EXPECT_GE(std::stod(m[1]), left) << m[5];
    EXPECT_GE(std::stod(m[2]), top) << m[5];
    EXPECT_LE(std::stod(m[3]), right) << m[5];
    EXPECT_LE(std::stod(m[4]), bottom) << m[5];
  }
  EXPECT_GT(words, 100);
}

#define REQUIRE_POPPLER()                                                                       \
  if (!have_tool("pdftotext") || !have_tool("pdftoppm") || !have_tool("pdfinfo")) {             \
    FAIL() << "pdftotext/pdftoppm/pdfinfo not found: install poppler-utils (scripts/install-deps.sh)"; \
  }

TEST(InspectionReport, ListsEachDiaphragmWithItsManholeOrWhyItHasNone) {
  REQUIRE_POPPLER();
  const std::string dir = fresh_dir("tunnelmap_report_plates");
  StationMap map = test::make_report_station_map();
  Diaphragm open;
  open.station_m = 4.012;
  open.seen_by_frames = 9;
  Manhole m;
  m.width_m = 0.452;
  m.height_m = 0.748;
  m.shape = "rounded_rectangle";
  m.corner_radius_m = 0.08;
  m.clearance_m[0] = 0.21;
  m.clearance_m[1] = 0.17;
  m.clearance_m[3] = 0.262;
  open.manhole = m;
  Diaphragm closed;
  closed.station_m = 8.034;
  closed.seen_by_frames = 3;
  closed.manhole_reason = "the rim was seen on 4 of 8 sides";
  Diaphragm end;
  end.kind = "end_wall";
  end.closed = true;
  end.station_m = 12.51;
  end.seen_by_frames = 6;
  end.manhole_reason = "no opening: the plate was seen closed across the section";
  map.girder.diaphragms = {open, closed, end};
  const std::string pdf = dir + "/report.pdf";
  write_inspection_report(pdf, report_input(map, write_fake_map_png(dir)));
  const std::string text = pdf_text(pdf);
  EXPECT_NE(text.find("Diaphragms and manholes"), std::string::npos);
  for (const char* value : {"4.012", "0.452", "0.748", "0.262", "0.170", "rounded rectangle (r 0.080)", "8.034",
                            "the rim was seen on 4 of 8", "D1", "D2", "end wall", "12.510"})  // the reason wraps in its column
    EXPECT_NE(text.find(value), std::string::npos) << value;
  EXPECT_EQ(text.find("D3"), std::string::npos);  // the end wall is not numbered as a diaphragm
  expect_words_inside_margins(pdf);
}

TEST(InspectionReport, ListsTheCompartmentsBetweenThePlates) {
  REQUIRE_POPPLER();
  const std::string dir = fresh_dir("tunnelmap_report_compartments");
  StationMap map = test::make_report_station_map();
  Compartment first;
  first.from_m = 0.35;
  first.to_m = 4.012;
  first.closed_to = true;
  first.width_m = 0.8214;
  first.height_m = 1.2987;
  first.stations_measured = 31;
  Compartment unmeasured;  // a gap between two plates, too short for a station
  unmeasured.from_m = 4.012;
  unmeasured.to_m = 4.331;
  unmeasured.closed_from = unmeasured.closed_to = true;
  unmeasured.width_m = unmeasured.height_m = NAN;
  map.girder.compartments = {first, unmeasured};
  const std::string pdf = dir + "/report.pdf";
  write_inspection_report(pdf, report_input(map, write_fake_map_png(dir)));
  const std::string text = pdf_text(pdf);
  const std::size_t heading = text.find("Compartments");
  ASSERT_NE(heading, std::string::npos);
  for (const char* value : {"C1", "C2", "0.350", "4.012", "3.662", "0.821", "1.299", "31", "4.331", "0.319",
                            "open \u2013 plate", "plate \u2013 plate"})
    EXPECT_NE(text.find(value, heading), std::string::npos) << value;
  // The unmeasured compartment's size is a dash, never a number.
  const std::size_t c2 = text.find("C2", heading);
  const std::string row = text.substr(c2, text.find('\n', text.find("plate \u2013 plate", c2)) - c2);
  EXPECT_EQ(row.find("nan"), std::string::npos) << row;
  EXPECT_NE(row.find("-"), std::string::npos) << row;
  expect_words_inside_margins(pdf);
}

// Poses 0.4 m apart are too close for every name: the plan names the poses to rescan first, and
// its legend keeps their entry.
TEST(InspectionReport, ThePlanNamesEveryPoseToRescanAmongCloseNeighbours) {
  REQUIRE_POPPLER();
  const std::string dir = fresh_dir("tunnelmap_report_close_poses");
  StationMap map = test::make_report_station_map();
  const PoseGroupStatus first = map.poses.front();
  map.poses.clear();
  for (int g = 0; g < 60; ++g) {
    PoseGroupStatus p = first;
    p.group = g;
    p.frames = {g};
    p.camera_to_world.translation() = map.origin + map.axis * (0.5 + 0.4 * g);
    p.rescan = g == 13 || g == 14 || g == 41;
    p.message = p.rescan ? "move and rescan: too_few_planes" : "ok";
    map.poses.push_back(p);
  }
  const std::string pdf = dir + "/report.pdf";
  write_inspection_report(pdf, report_input(map, write_fake_map_png(dir)));
  const std::string text = pdf_text(pdf);
  const std::size_t plan = text.find("Plan (top view"), after = text.find("Width against station");
  ASSERT_NE(plan, std::string::npos);
  ASSERT_NE(after, std::string::npos);
  const std::string drawn = text.substr(plan, after - plan);
  for (const char* name : {"P13", "P41", "pose to rescan"}) EXPECT_NE(drawn.find(name), std::string::npos) << name;
  EXPECT_EQ(drawn.find("P14"), std::string::npos);  // beside P13: no room for both names
  expect_words_inside_margins(pdf);
}

TEST(InspectionReport, HoldsSectionsOutOfToleranceStationsAndRescanPose) {
  REQUIRE_POPPLER();
  const std::string dir = fresh_dir("tunnelmap_report");
  const StationMap map = test::make_report_station_map();
  const std::string pdf = dir + "/report.pdf";
  write_inspection_report(pdf, report_input(map, write_fake_map_png(dir)));
  ASSERT_TRUE(fs::exists(pdf));
  const std::string text = pdf_text(pdf);
  // Header: input, date, version, design and tolerance.
  EXPECT_NE(text.find("Tunnel inspection report"), std::string::npos);
  EXPECT_NE(text.find("/data/girder-7/dataset.json"), std::string::npos);
  EXPECT_NE(text.find("2024-05-14 09:30"), std::string::npos);
  EXPECT_NE(text.find(std::string("TunnelMap ") + TUNNELMAP_VERSION), std::string::npos);
  EXPECT_NE(text.find("0.820 \u00d7 1.300 m"), std::string::npos);
  EXPECT_NE(text.find("\u00b1 10 mm"), std::string::npos);
  EXPECT_NE(text.find("grow.angle_deg"), std::string::npos);
  EXPECT_NE(text.find("normals.smoothing_px"), std::string::npos);
  // Summary.
  EXPECT_NE(text.find("4 of 240 stations"), std::string::npos) << text;
  EXPECT_NE(text.find("1 of 6"), std::string::npos);
  // Every section's extent and size.
  for (const Section& s : map.sections) {
    EXPECT_NE(text.find(fmt("%.2f", s.from_m)), std::string::npos);
    EXPECT_NE(text.find(fmt("%.2f", s.to_m)), std::string::npos);
    EXPECT_NE(text.find(fmt("%.3f", s.width_m)), std::string::npos) << s.width_m;
    EXPECT_NE(text.find(fmt("%.3f", s.height_m)), std::string::npos) << s.height_m;
  }
  EXPECT_NE(text.find("+7.0"), std::string::npos);  // S2 width against the design
  // The out-of-tolerance stations with their values and deviations.
  for (const char* station : {"11.05", "11.15", "11.25", "19.45"})
    EXPECT_NE(text.find(station), std::string::npos) << station;
  EXPECT_NE(text.find("0.834"), std::string::npos);
  EXPECT_NE(text.find("+13.5"), std::string::npos);
  EXPECT_NE(text.find("1.287"), std::string::npos);
  EXPECT_NE(text.find("-13.0"), std::string::npos);
  // The pose to rescan, its frames and message; the good poses are not listed.
  EXPECT_NE(text.find("P3"), std::string::npos);
  EXPECT_NE(text.find("21-27"), std::string::npos);
  EXPECT_NE(text.find("move and rescan: too_few_planes"), std::string::npos);
  EXPECT_EQ(text.find("14-20"), std::string::npos);
  // The roof out of view at 4.05-4.45 m is a stretch to rescan; the last two stations' roof
  // from the design (0.2 m) is shorter than a section and is not.
  const std::size_t stretches = text.find("Stretches to rescan");
  ASSERT_NE(stretches, std::string::npos);
  std::size_t at = stretches;
  for (const char* cell : {"4.00", "4.50", "0.50", "height", "no frame measured the height here"}) {
    at = text.find(cell, at);
    ASSERT_NE(at, std::string::npos) << cell;
  }
  EXPECT_EQ(text.find("23.80", stretches), std::string::npos);
  // Page numbers on every page.
  const int pages = pdf_pages(pdf);
  EXPECT_GE(pages, 2);
  EXPECT_NE(text.find("page " + std::to_string(pages) + " of " + std::to_string(pages)), std::string::npos);
  expect_words_inside_margins(pdf);

  // Page 1 as an image: not blank, and the plan's coloured shading is there.
  ASSERT_EQ(std::system(("pdftoppm -r 50 -png -f 1 -l 1 -singlefile '" + pdf + "' '" + dir + "/page1'").c_str()), 0);
  QImage page(QString::fromStdString(dir + "/page1.png"));
  ASSERT_FALSE(page.isNull());
  EXPECT_NEAR(page.width(), 413, 3);  // A4 at 50 dpi
  int ink = 0, colour = 0;
  for (int y = 0; y < page.height(); ++y)
    for (int x = 0; x < page.width(); ++x) {
      const QColor c = page.pixelColor(x, y);
      if (c.red() < 200 || c.green() < 200 || c.blue() < 200) ++ink;
      if (c.saturation() > 40 && c.value() > 60) ++colour;
    }
  const int total = page.width() * page.height();
  EXPECT_GT(ink, total / 100) << "page 1 is (nearly) blank";
  EXPECT_GT(colour, total / 200) << "page 1 has no coloured plan";
}

TEST(InspectionReport, SaysNoneWhenNothingIsOutOfToleranceOrToRescanAndWhyThereIsNoImage) {
  REQUIRE_POPPLER();
  const std::string dir = fresh_dir("tunnelmap_report_none");
  StationMap map = test::make_report_station_map();
  for (Station& s : map.stations) s.out_of_tolerance = false;
  for (PoseGroupStatus& p : map.poses) p.rescan = false;
  // The roof seen all along but at the last two stations (0.2 m, shorter than a section).
  for (int i = 40; i <= 44; ++i) map.stations[static_cast<std::size_t>(i)].height_source = DimensionSource::Measured;
  const std::string pdf = dir + "/report.pdf";
  write_inspection_report(pdf, report_input(map, ""));
  const std::string text = pdf_text(pdf);
  EXPECT_NE(text.find("none: every station is within"), std::string::npos);
  EXPECT_NE(text.find("none: every pose found the tunnel"), std::string::npos);
  EXPECT_NE(text.find("none: no unmeasured stretch is long enough"), std::string::npos);
  EXPECT_NE(text.find("tunnelmap-render was not found next to tunnelmap-cli"), std::string::npos);
}

TEST(InspectionReport, CarriesTheMappingsNotesAsTheCommandLinePrintsThem) {
  REQUIRE_POPPLER();
  const std::string dir = fresh_dir("tunnelmap_report_notes");
  const StationMap map = test::make_report_station_map();
  InspectionReportInput in = report_input(map, "");
  const std::string unchecked = "pose 3 (frames 6-7): nothing it saw was seen from another pose, so nothing checks it";
  in.notes = {unchecked + "; mapped where its pose puts it"};
  write_inspection_report(dir + "/notes.pdf", in);
  const std::string text = pdf_text(dir + "/notes.pdf", 1, 1);
  EXPECT_NE(text.find("Notes"), std::string::npos);
  EXPECT_NE(text.find(unchecked), std::string::npos) << text;  // on one line
  expect_words_inside_margins(dir + "/notes.pdf");
  // Nothing to note: no heading.
  write_inspection_report(dir + "/plain.pdf", report_input(map, ""));
  EXPECT_EQ(pdf_text(dir + "/plain.pdf").find("Notes"), std::string::npos);
}

// The box around a section's label in the plan: the words on the line from "S<n>" on, in pixels
// of the page rendered at `dpi`, and the page it is on (0 when not found).
struct LabelBox {
  int page = 0;
  QRectF box;
};

LabelBox plan_label_box(const std::string& pdf, const std::string& name, double dpi) {
  const std::regex word(R"re(<word xMin="([-0-9.]+)" yMin="([-0-9.]+)" xMax="([-0-9.]+)" yMax="([-0-9.]+)">([^<]*)</word>)re");
  for (int page = 1; page <= pdf_pages(pdf); ++page) {
    const std::string html = pdf + ".p" + std::to_string(page) + ".html";
    const std::string cmd = "pdftotext -bbox -f " + std::to_string(page) + " -l " + std::to_string(page) + " '" + pdf + "' '" + html + "'";
    EXPECT_EQ(std::system(cmd.c_str()), 0);
    const std::string text = read_file(html);
    LabelBox found;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), word); it != std::sregex_iterator(); ++it) {
      const QRectF w(QPointF(std::stod((*it)[1]), std::stod((*it)[2])), QPointF(std::stod((*it)[3]), std::stod((*it)[4])));
      if (found.page == 0 && (*it)[5] == name) found = {page, w};
      else if (found.page != 0 && std::abs(w.top() - found.box.top()) < 0.5 && w.left() > found.box.left())
        found.box = found.box.united(w);
    }
    if (found.page != 0) {
      const double k = dpi / 72.0;
      found.box = QRectF(found.box.topLeft() * k, found.box.bottomRight() * k);
      return found;
    }
  }
  return {};
}

TEST(InspectionReport, APlatesLineInThePlanDoesNotRunThroughTheSectionsLabel) {
  // A plate without an opening (a whole line across the band) in the middle of each section,
  // where the section's name and size are centred.
  REQUIRE_POPPLER();
  const std::string dir = fresh_dir("tunnelmap_report_plan_label");
  StationMap map = test::make_report_station_map();
  for (const Section& s : map.sections) {
    Diaphragm d;
    d.station_m = 0.5 * (s.from_m + s.to_m);
    d.closed = true;
    map.girder.diaphragms.push_back(d);
  }
  const std::string pdf = dir + "/report.pdf";
  write_inspection_report(pdf, report_input(map, ""));
  const double dpi = 144.0;
  const LabelBox label = plan_label_box(pdf, "S2", dpi);
  ASSERT_GT(label.page, 0);
  EXPECT_GT(label.box.width(), 3.0 * label.box.height());  // the name and its size
  const std::string page = std::to_string(label.page);
  ASSERT_EQ(std::system(("pdftoppm -r 144 -png -f " + page + " -l " + page + " -singlefile '" + pdf + "' '" + dir + "/plan'").c_str()), 0);
  QImage img(QString::fromStdString(dir + "/plan.png"));
  ASSERT_FALSE(img.isNull());
  // The plate's line (grey 120, 128, 140) runs down the band below the label; inside the label's
  // box the same columns hold the section's shade and the text, not the line (the text's
  // antialiased edges may share the grey, a few pixels).
  const auto plate_grey = [&](int x, int y) {
    const QColor c = img.pixelColor(x, y);
    return std::abs(c.red() - 120) < 12 && std::abs(c.green() - 128) < 12 && std::abs(c.blue() - 140) < 12;
  };
  const QRect box = label.box.toAlignedRect();
  int line_columns = 0;
  for (int x = box.left(); x <= box.right(); ++x) {
    int below = 0, inside = 0;
    for (int y = box.bottom() + 3; y <= box.bottom() + 12; ++y) below += plate_grey(x, y) ? 1 : 0;
    if (below < 9) continue;
    ++line_columns;
    for (int y = box.top() + 1; y < box.bottom(); ++y) inside += plate_grey(x, y) ? 1 : 0;
    EXPECT_LT(inside, (box.height() - 2) / 3) << "the plate's line runs through the label at x = " << x;
  }
  EXPECT_GE(line_columns, 1);  // the plate does pass under the label
}

TEST(InspectionReport, WithoutDesignSaysNone) {
  REQUIRE_POPPLER();
  const std::string dir = fresh_dir("tunnelmap_report_nodesign");
  StationMap map = test::make_report_station_map();
  map.options.design_width_m.reset();
  map.options.design_height_m.reset();
  for (Station& s : map.stations) {
    s.width_dev_mm.reset();
    s.height_dev_mm.reset();
    s.out_of_tolerance = false;
  }
  const std::string pdf = dir + "/report.pdf";
  write_inspection_report(pdf, report_input(map, ""));
  const std::string text = pdf_text(pdf);
  EXPECT_NE(text.find("Design"), std::string::npos);
  EXPECT_NE(text.find("none: no design cross-section was given"), std::string::npos);
  EXPECT_EQ(text.find("width (mm)"), std::string::npos);  // no deviation columns
}

// A design far from the tunnel puts every station out of tolerance: the table runs over several
// pages and every page with its rows starts with its header.
TEST(InspectionReport, LongTableRepeatsItsHeaderOnEveryPage) {
  REQUIRE_POPPLER();
  const std::string dir = fresh_dir("tunnelmap_report_long");
  StationMap map = test::make_report_station_map();
  map.options.design_width_m = 0.80;
  for (Station& s : map.stations) {
    s.width_dev_mm = (s.width_m - 0.80) * 1000.0;
    s.out_of_tolerance = true;
  }
  const std::string pdf = dir + "/report.pdf";
  write_inspection_report(pdf, report_input(map, ""));
  const int pages = pdf_pages(pdf);
  ASSERT_GE(pages, 5);
  // A row of the table: its two source columns side by side.
  const std::regex row("(measured|context|design) +(measured|context|design)");
  int pages_with_rows = 0;
  for (int page = 1; page <= pages; ++page) {
    const std::string text = pdf_text(pdf, page, page);
    if (!std::regex_search(text, row)) continue;
    ++pages_with_rows;
    EXPECT_NE(text.find("Station (m)"), std::string::npos) << "page " << page << " has rows but no header";
    EXPECT_NE(text.find("Height from"), std::string::npos) << "page " << page;
  }
  EXPECT_GE(pages_with_rows, 3);
  const std::string all = pdf_text(pdf);
  EXPECT_NE(all.find("240 of 240 stations"), std::string::npos);
  EXPECT_NE(all.find("23.95"), std::string::npos);  // the last station is listed
}

TEST(InspectionReport, NothingRunsOffThePageEvenWithALongInputPath) {
  REQUIRE_POPPLER();
  const std::string dir = fresh_dir("tunnelmap_report_margins");
  const StationMap map = test::make_report_station_map();
  InspectionReportInput in = report_input(map, "");
  in.input = "/surveys/" + std::string(70, 'a') + "/" + std::string(70, 'b') + "/girder_7_dataset.json";
  in.params["tunnel.a_parameter_with_a_rather_long_key_name"] = "a text value with words";
  const std::string pdf = dir + "/report.pdf";
  write_inspection_report(pdf, in);
  expect_words_inside_margins(pdf);
}

TEST(InspectionReport, UnwritablePathGivesInputErrorAndLeavesNoFile) {
  const std::string dir = fresh_dir("tunnelmap_report_unwritable");
  const StationMap map = test::make_report_station_map();
  const std::string missing = dir + "/no/such/folder/report.pdf";
  try {
    write_inspection_report(missing, report_input(map, ""));
    FAIL() << "no error for a missing folder";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), missing);
    EXPECT_NE(std::string(e.what()).find(missing), std::string::npos);
  }
  // The path is a folder: nothing replaces it and no temporary file stays beside it.
  const std::string folder = dir + "/report.pdf";
  fs::create_directories(folder);
  EXPECT_THROW(write_inspection_report(folder, report_input(map, "")), OutputPathError);  // bad usage
  EXPECT_TRUE(fs::is_directory(folder));
  int entries = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    ++entries;
    EXPECT_EQ(e.path().filename(), "report.pdf") << "left behind: " << e.path();
  }
  EXPECT_EQ(entries, 1);
  EXPECT_FALSE(fs::exists(dir + "/no"));
}

TEST(InspectionReport, ExistingReportIsReplacedWhole) {
  const std::string dir = fresh_dir("tunnelmap_report_replace");
  const std::string pdf = dir + "/report.pdf";
  { std::ofstream(pdf) << "old"; }
  const StationMap map = test::make_report_station_map();
  write_inspection_report(pdf, report_input(map, ""));
  EXPECT_EQ(read_file(pdf).substr(0, 5), "%PDF-");
  EXPECT_GT(fs::file_size(pdf), 10000u);
  int entries = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    ++entries;
    EXPECT_EQ(e.path().filename(), "report.pdf") << "left behind: " << e.path();
  }
  EXPECT_EQ(entries, 1);
}

TEST(InspectionReport, MapThatWasNotBuiltStillGivesAReportThatSaysWhy) {
  REQUIRE_POPPLER();
  const std::string dir = fresh_dir("tunnelmap_report_not_built");
  StationMap map;
  map.status = "no_poses";
  map.reason = "the dataset has no camera poses or arm joints";
  const std::string pdf = dir + "/report.pdf";
  write_inspection_report(pdf, report_input(map, ""));
  const std::string text = pdf_text(pdf);
  EXPECT_NE(text.find("not built: no_poses"), std::string::npos) << text;
  EXPECT_NE(text.find("no camera poses or arm joints"), std::string::npos);
  EXPECT_NE(text.find("Nothing to draw"), std::string::npos);
  EXPECT_NE(text.find("none: no stretch of constant cross-section"), std::string::npos);
  expect_words_inside_margins(pdf);
}

TEST(InspectionReport, NoMapIsAnInputError) {
  InspectionReportInput in;
  EXPECT_THROW(write_inspection_report(::testing::TempDir() + "x.pdf", in), InputError);
}

}  // namespace
}  // namespace tunnelmap
