// Pixel <-> direction of the skydome projections (api/skydome/skydome_projection.h, docs/viewer.md):
// fisheye equidistant, North up, East left; latlong North at the centre column, East right,
// zenith on top. Angles in degrees, azimuth from North through East.
export function toPixel(projection, zenithDeg, azimuthDeg, width, height) {
  const az = azimuthDeg * Math.PI / 180;
  if (projection === 'fisheye') {
    const r = (zenithDeg / 90) * (width / 2);
    return [width / 2 - r * Math.sin(az), height / 2 - r * Math.cos(az)];
  }
  const u = ((azimuthDeg / 360 + 0.5) % 1 + 1) % 1;
  return [u * width, (zenithDeg / 180) * height];
}

export function toDirection(projection, x, y, width, height) {
  if (projection === 'fisheye') {
    const dx = (width / 2 - x) / (width / 2), dy = (height / 2 - y) / (height / 2);
    const r = Math.hypot(dx, dy);
    if (r > 1) return null;
    let az = Math.atan2(dx, dy) * 180 / Math.PI;
    if (az < 0) az += 360;
    return { zenith: r * 90, azimuth: az };
  }
  const zenith = (y / height) * 180;
  if (zenith > 90) return null;
  let az = (x / width) * 360 - 180;
  if (az < 0) az += 360;
  return { zenith, azimuth: az };
}
