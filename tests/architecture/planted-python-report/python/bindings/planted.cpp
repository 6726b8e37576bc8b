// Planted: the Python bindings (rank 2) including report/ (its sibling of rank 2). Must fail.
#include "report/report_writer.hpp"
