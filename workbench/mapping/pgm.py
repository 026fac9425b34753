"""Read and write the greyscale images of map_server maps (binary PGM; other formats via Pillow)."""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from workbench.limits import MiB, read_bytes_bounded
from workbench.mapping.errors import MapFileError

#: Most pixels a map image may have (5000 x 5000; gmapping's default map is 4000 x 4000).
MAX_MAP_PIXELS = 25_000_000
#: Largest map image file read, bytes.
MAX_MAP_IMAGE_BYTES = 256 * MiB

_TOKEN = re.compile(rb"(#[^\n]*\n)|(\S+)")


def write_pgm(path: Path, pixels: np.ndarray, comment: str | None = None) -> None:
    """Write ``(height, width)`` uint8 pixels as a binary (P5) PGM, rows top-down.

    Raises:
        MapFileError: when the file cannot be written.
    """
    pixels = np.ascontiguousarray(pixels, dtype=np.uint8)
    header = "P5\n"
    if comment:
        header += f"# {comment}\n"
    header += f"{pixels.shape[1]} {pixels.shape[0]}\n255\n"
    try:
        with open(path, "wb") as stream:
            stream.write(header.encode("ascii"))
            stream.write(pixels.tobytes())
    except OSError as exc:
        raise MapFileError(
            f"cannot write map image: {exc.strerror}",
            path=path,
            hint="choose a writable directory with --out",
        ) from None


def _read_pnm(path: Path, raw: bytes) -> np.ndarray:
    magic = raw[:2]
    values: list[int] = []
    position = 2
    while len(values) < 3:
        match = _TOKEN.search(raw, position)
        if match is None:
            raise MapFileError("truncated PGM header", path=path)
        position = match.end()
        if match.group(2) is not None:
            try:
                values.append(int(match.group(2)))
            except ValueError:
                raise MapFileError(f"bad PGM header field {match.group(2)!r}", path=path) from None
    width, height, maxval = values
    if width <= 0 or height <= 0 or not 0 < maxval < 65536:
        raise MapFileError(f"bad PGM size {width}x{height} or maxval {maxval}", path=path)
    _check_pixels(width, height, path)
    if magic == b"P5":
        body = raw[position + 1 :]
        dtype = np.dtype(">u2") if maxval > 255 else np.dtype(np.uint8)
        need = width * height * dtype.itemsize
        if len(body) < need:
            raise MapFileError(
                f"PGM pixel data is truncated ({len(body)} of {need} bytes)", path=path
            )
        pixels = np.frombuffer(body[:need], dtype=dtype).reshape(height, width)
    else:  # P2, plain text
        numbers = raw[position:].split()
        if len(numbers) < width * height:
            raise MapFileError("PGM pixel data is truncated", path=path)
        try:
            pixels = np.array(numbers[: width * height], dtype=np.int64).reshape(height, width)
        except ValueError:
            raise MapFileError("PGM pixel data holds a non-number", path=path) from None
    if maxval != 255:
        pixels = np.rint(pixels.astype(float) * 255.0 / maxval)
    return np.clip(pixels, 0, 255).astype(np.uint8)


def _check_pixels(width: int, height: int, path: Path) -> None:
    if width * height > MAX_MAP_PIXELS:
        raise MapFileError(
            f"the map image is {width} x {height} pixels, more than the {MAX_MAP_PIXELS:,} a "
            "map may have",
            path=path,
            hint="use a coarser resolution, or crop the map",
        )


def read_image(path: Path) -> tuple[np.ndarray, bool]:
    """Read a map image as ``(height, width, channels)`` uint8, rows top-down.

    Returns:
        The pixels and whether the last channel is alpha.

    Raises:
        MapFileError: for a missing file or one that is not an image.
    """
    if not path.exists():
        raise MapFileError(
            "map image not found", path=path, hint="check the 'image:' entry of the map YAML"
        )
    raw = read_bytes_bounded(path, "map image", MAX_MAP_IMAGE_BYTES, MapFileError)
    if raw[:2] in (b"P5", b"P2"):
        return _read_pnm(path, raw)[:, :, None], False
    import io

    from PIL import Image, UnidentifiedImageError

    try:
        with Image.open(io.BytesIO(raw)) as image:
            _check_pixels(*image.size, path)  # before the pixels are decompressed
            image.load()
            mode = image.mode
            if mode in ("1", "L", "P", "I", "I;16", "F"):
                image = image.convert("L")
            elif mode in ("LA", "PA"):
                image = image.convert("LA")
            elif mode in ("RGBA", "RGBa"):
                image = image.convert("RGBA")
            else:
                image = image.convert("RGB")
            pixels = np.asarray(image, dtype=np.uint8)
            has_alpha = image.mode in ("LA", "RGBA")
    except Image.DecompressionBombError as error:  # far too large: Pillow refuses to open it
        raise MapFileError(
            f"the map image has more than the {MAX_MAP_PIXELS:,} pixels a map may have ({error})",
            path=path,
            hint="use a coarser resolution, or crop the map",
        ) from None
    except (UnidentifiedImageError, OSError, ValueError):
        raise MapFileError(
            "not an image map_server can read (expected a PGM, PNG or similar)", path=path
        ) from None
    if pixels.ndim == 2:
        pixels = pixels[:, :, None]
    return pixels, has_alpha
