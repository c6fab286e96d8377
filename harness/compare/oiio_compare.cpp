// countFailingPixels: OpenImageIO's ImageBufAlgo::compare on the prepared
// planes (the failing pixels' positions come from the texel loop).
#include "compare/image_pair.h"

#ifdef RAYSPEC_WITH_OIIO
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#endif

namespace rayspec {

PixelCount countFailingPixels(const ImagePair& p) {
  PixelCount loop = countFailingPixelsLoop(p);
#ifdef RAYSPEC_WITH_OIIO
  if (p.width == 0 || p.height == 0) return loop;
  const OIIO::ImageSpec spec(static_cast<int>(p.width), static_cast<int>(p.height),
                             static_cast<int>(p.channels), OIIO::TypeDesc::FLOAT);
  OIIO::ImageBuf device(spec, const_cast<float*>(p.difference.data()));
  OIIO::ImageBuf reference(spec);
  OIIO::ImageBufAlgo::zero(reference);
  const OIIO::ImageBufAlgo::CompareResults r =
      OIIO::ImageBufAlgo::compare(device, reference, 1.0f, 1.0f);
  // OpenImageIO 2.4 sets r.error whenever pixels fail; a real error is on the buffers.
  if (device.has_error() || reference.has_error()) return loop;
  PixelCount c;
  c.by_oiio = true;
  c.failing = r.nfail;
  c.max_error = r.maxerror;
  c.first = loop.first;
  return c;
#else
  return loop;
#endif
}

}  // namespace rayspec
