// How the preview turns a port's float pixels into something to look at: an exposure in EV
// for linear images, then an sRGB encode for light (PreviewEncoding says which), and the sRGB
// values of a display-encoded (ldr) image as they are; all channels or one as grey. And the
// read-out of one pixel's own values.
#pragma once

#include <QImage>
#include <QString>

#include "editor/preview.h"

namespace lg::editor {

enum class PreviewChannel { rgb, red, green, blue, alpha };

// Non-finite pixels show magenta, so that a NaN is seen rather than hidden.
QImage display_image(const PreviewImage& image, double exposure_ev, PreviewChannel channel);

// "x 12, y 34: 0.1234 0.5 1 1" (float RGBA before exposure); empty outside the image.
QString pixel_readout(const PreviewImage& image, int x, int y);

}  // namespace lg::editor
