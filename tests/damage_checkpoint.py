#!/usr/bin/python3
"""Copy a checkpoint and damage the copy, for tests/check_bad_input.sh.

Usage: damage_checkpoint.py SOURCE_DIR COPY_DIR DAMAGE

DAMAGE is one of
  payload         state.bin keeps its header, the rest is random bytes
  size            state.bin's count of sections is 2^62
  flip            three bytes of state.bin flipped
  mesh            membrane.mesh overwritten with random bytes
  truncated       membrane.mesh_fixed.data cut to half its length
  manifest        the manifest removed
  format-1        state.bin and no manifest as an older pneuma wrote them
  forged-size     the first section's length 2^62, the manifest rewritten
                  to match (only the lengths in state.bin can tell)
  forged-payload  every section's value random, the manifest rewritten to
                  match (only the unpacking can tell)
  forged:OLD:NEW  the text OLD (once in state.bin, e.g. a parameter value
                  the checkpoint stored) replaced by NEW of the same
                  length, the manifest rewritten to match
The random bytes come from a fixed seed: the same damage every time.
"""
import os
import random
import shutil
import struct
import sys
import zlib

MAGIC = b"pneuma-checkpoint-2\n"
HEADER = "pneuma checkpoint manifest, format 2"


def reseal(directory):
    """Rewrite the manifest for the files as they are now."""
    text = HEADER + "\n"
    for name in sorted(os.listdir(directory)):
        if name == "manifest":
            continue
        data = open(os.path.join(directory, name), "rb").read()
        text += f"{zlib.crc32(data):08x} {len(data)} {name}\n"
    text += f"end {zlib.crc32(text.encode()):08x}\n"
    open(os.path.join(directory, "manifest"), "w").write(text)


def sections(data):
    """(offset of the length, offset of the value, length) per section."""
    pos, result = len(MAGIC) + 8, []
    (n,) = struct.unpack_from("<Q", data, len(MAGIC))
    for _ in range(n):
        (name_length,) = struct.unpack_from("<Q", data, pos)
        pos += 8 + name_length
        (length,) = struct.unpack_from("<Q", data, pos)
        result.append((pos, pos + 8, length))
        pos += 8 + length
    return result


def main(source, copy, damage):
    shutil.rmtree(copy, ignore_errors=True)
    shutil.copytree(source, copy)
    rng = random.Random(46)
    state = os.path.join(copy, "state.bin")
    data = bytearray(open(state, "rb").read())
    if damage == "payload":
        data[len(MAGIC):] = rng.randbytes(len(data) - len(MAGIC))
    elif damage == "size":
        struct.pack_into("<Q", data, len(MAGIC), 2**62)
    elif damage == "flip":
        for k in rng.sample(range(len(MAGIC), len(data)), 3):
            data[k] ^= 0xFF
    elif damage == "mesh":
        mesh = os.path.join(copy, "membrane.mesh")
        size = os.path.getsize(mesh)
        open(mesh, "wb").write(rng.randbytes(size))
    elif damage == "truncated":
        fixed = os.path.join(copy, "membrane.mesh_fixed.data")
        os.truncate(fixed, os.path.getsize(fixed) // 2)
    elif damage == "manifest":
        os.remove(os.path.join(copy, "manifest"))
    elif damage == "format-1":
        data[:len(MAGIC)] = b"pneuma-checkpoint-1"
        os.remove(os.path.join(copy, "manifest"))
    elif damage == "forged-size":
        struct.pack_into("<Q", data, sections(data)[0][0], 2**62)
    elif damage == "forged-payload":
        for _, start, length in sections(data):
            data[start:start + length] = rng.randbytes(length)
    elif damage.startswith("forged:"):
        _, old, new = damage.split(":")
        assert len(old) == len(new) and data.count(old.encode()) == 1
        data = data.replace(old.encode(), new.encode())
    else:
        sys.exit(f"damage_checkpoint.py: unknown damage '{damage}'")
    open(state, "wb").write(data)
    if damage.startswith("forged"):
        reseal(copy)


if __name__ == "__main__":
    main(*sys.argv[1:4])
