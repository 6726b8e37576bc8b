#include "design/project.hpp"

namespace spiral::design {

DnvOsE301Factors dnv_os_e301_defaults(int consequence_class) {
  // DNV-OS-E301 (2010) Ch. 2 Sec. 2: ULS Table 1, ALS Table 2.
  DnvOsE301Factors factors;
  factors.consequence_class = consequence_class;
  if (consequence_class == 2) {
    factors.uls_mean = 1.40;
    factors.uls_dynamic = 2.10;
  }
  return factors;
}

const char* to_string(AttachmentKind kind) {
  switch (kind) {
    case AttachmentKind::clump:
      return "clump";
    case AttachmentKind::buoy:
      return "buoy";
  }
  return "?";
}

const char* to_string(RiserKind kind) {
  switch (kind) {
    case RiserKind::scr:
      return "scr";
    case RiserKind::lazy_wave:
      return "lazy_wave";
    case RiserKind::flexible:
      return "flexible";
  }
  return "?";
}

const char* to_string(WaveSpectrum spectrum) {
  switch (spectrum) {
    case WaveSpectrum::jonswap:
      return "jonswap";
    case WaveSpectrum::pierson_moskowitz:
      return "pierson_moskowitz";
  }
  return "?";
}

const char* to_string(WindSpectrum spectrum) {
  switch (spectrum) {
    case WindSpectrum::api:
      return "api";
    case WindSpectrum::npd:
      return "npd";
    case WindSpectrum::none:
      return "none";
  }
  return "?";
}

const char* to_string(MooringCode code) {
  switch (code) {
    case MooringCode::api_rp_2sk:
      return "api_rp_2sk";
    case MooringCode::dnv_os_e301:
      return "dnv_os_e301";
  }
  return "?";
}

}  // namespace spiral::design
