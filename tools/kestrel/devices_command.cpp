// `kestrel devices`: the V4L2 capture devices and serial ports on this machine, with what each
// offers, and which look like an oCamS-1CGN-U (its camera by its name, its IMU by the camera's
// USB ids). For field checks before a flight (docs/hardware.md). Exits 0 when it finds none.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>

#include "commands.hpp"
#include "kestrel/v4l2/ocams_modes.hpp"
#include "kestrel/v4l2/v4l2_camera.hpp"

namespace kestrel::cli {

namespace {

namespace fs = std::filesystem;

std::string first_line(const fs::path& file) {
  std::ifstream in(file);
  std::string s;
  std::getline(in, s);
  return s;
}

struct SerialPortInfo {
  std::string path, vendor, product_id, product;
};

// /sys/class/tty/ttyACM0/device is the USB interface; its parent holds the device's ids.
std::vector<SerialPortInfo> serial_ports() {
  std::vector<SerialPortInfo> out;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator("/sys/class/tty", ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("ttyACM", 0) != 0 && name.rfind("ttyUSB", 0) != 0) continue;
    const fs::path usb = fs::canonical(entry.path() / "device", ec).parent_path();
    out.push_back(
        {"/dev/" + name, first_line(usb / "idVendor"), first_line(usb / "idProduct"), first_line(usb / "product")});
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.path < b.path; });
  return out;
}

}  // namespace

int devices_command() {
  const auto cameras = v4l2::list_video_devices(v4l2::system_v4l2_io());
  bool found = false;
  std::cout << "Video capture devices:\n";
  if (cameras.empty()) std::cout << "  none\n";
  for (const auto& d : cameras) {
    const bool ocams = d.card.find("oCamS") != std::string::npos;
    found = found || ocams;
    std::cout << "  " << d.path << "  " << d.card << " (" << d.driver << ", " << d.bus << ")"
              << (ocams ? "  <- an oCamS: device: " + d.path : "") << "\n";
    for (const auto& m : d.modes) {
      std::cout << "    " << v4l2::fourcc_text(m.fourcc) << " " << m.width << "x" << m.height << " @";
      for (double f : m.fps) std::cout << " " << f;
      if (ocams && !ocams::ocams_streams(m.width, m.height, m.fps.empty() ? 0 : static_cast<int>(m.fps.front())))
        std::cout << "  (not in firmware R1811's table)";
      std::cout << "\n";
    }
  }
  std::cout << "Serial ports:\n";
  const auto ports = serial_ports();
  if (ports.empty()) std::cout << "  none\n";
  for (const auto& p : ports) {
    // The oCamS's IMU is the camera board's CDC-ACM interface: the camera's Cypress FX3 ids.
    const bool imu = p.vendor == "04b4" && (p.product_id == "00f9" || p.product_id == "00f8");
    std::cout << "  " << p.path << "  " << p.vendor << ":" << p.product_id << " " << p.product
              << (imu ? "  <- the oCamS IMU, if the camera is the only FX3 board: port: " + p.path : "") << "\n";
  }
  if (!found) std::cout << "No oCamS found. docs/hardware.md: wiring and the udev rule.\n";
  return kOk;
}

}  // namespace kestrel::cli
