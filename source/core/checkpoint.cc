#include <pneuma/core/checkpoint.h>
#include <pneuma/core/collective_error.h>
#include <pneuma/core/input_error.h>
#include <pneuma/core/input_layout.h>
#include <pneuma/core/output.h>

#include <boost/crc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace pneuma
{
  using namespace dealii;

  namespace
  {
    namespace fs = std::filesystem;

    /// First bytes of state.bin: the format and its version.
    const std::string magic = "pneuma-checkpoint-2\n";
    /// The first line of state.bin of format 1 (no manifest, no lengths).
    const std::string magic_1 = "pneuma-checkpoint-1";
    /// First line of the manifest, and its part before the version.
    const std::string manifest_header = "pneuma checkpoint manifest, format 2";
    const std::string manifest_family = "pneuma checkpoint manifest, format ";

    std::string
    hex(const std::uint32_t crc)
    {
      char buffer[16];
      std::snprintf(buffer, sizeof(buffer), "%08x", crc);
      return buffer;
    }

    std::uint32_t
    crc_of(const std::string &text)
    {
      boost::crc_32_type crc;
      crc.process_bytes(text.data(), text.size());
      return crc.checksum();
    }

    /// The CRC32 of the file @p name; false if it cannot be read whole.
    bool
    file_crc(const std::string &name, std::uint32_t &result)
    {
      std::ifstream      in(name, std::ios::binary);
      boost::crc_32_type crc;
      std::vector<char>  buffer(1 << 20);
      while (in)
        {
          in.read(buffer.data(), buffer.size());
          crc.process_bytes(buffer.data(), in.gcount());
        }
      result = crc.checksum();
      return in.eof();
    }

    /// A file the manifest lists.
    struct ManifestEntry
    {
      std::uint32_t crc  = 0;
      std::uint64_t size = 0;
      std::string   name;
    };

    /**
     * Read `manifest` in @p dir into @p entries; the error ("'file' what",
     * empty: none).
     */
    std::string
    read_manifest(const std::string &dir, std::vector<ManifestEntry> &entries)
    {
      const std::string file = dir + "/manifest";
      std::ifstream     in(file, std::ios::binary);
      if (!in)
        return "'" + file
               + "' is missing: the checkpoint is incomplete or was written "
                 "by an older pneuma, and cannot be verified";
      std::string              line, text;
      std::vector<std::string> lines;
      while (std::getline(in, line))
        lines.push_back(line);
      const std::string name = "'" + file + "' ";
      if (lines.empty() || lines[0] != manifest_header)
        return lines.empty() || lines[0].rfind(manifest_family, 0) != 0
                 ? name + "is not a pneuma checkpoint manifest"
                 : name + "is of checkpoint format "
                     + lines[0].substr(manifest_family.size())
                     + "; this pneuma reads format 2";
      for (unsigned int k = 0; k + 1 < lines.size(); ++k)
        text += lines[k] + "\n";
      if (lines.back().rfind("end ", 0) != 0)
        return name + "is truncated (no end line)";
      if (lines.back() != "end " + hex(crc_of(text)))
        return name + "is damaged (its CRC32 does not match its end line)";
      for (unsigned int k = 1; k + 1 < lines.size(); ++k)
        {
          std::istringstream fields(lines[k]);
          std::string        crc;
          ManifestEntry      e;
          fields >> crc >> e.size >> std::ws;
          std::getline(fields, e.name);
          if (crc.size() != 8 || !fields.eof() || e.name.empty()
              || e.name.find('/') != std::string::npos || e.name == ".."
              || crc.find_first_not_of("0123456789abcdef") != crc.npos)
            return name + "is damaged (line " + std::to_string(k + 1) + ")";
          e.crc = std::stoul(crc, nullptr, 16);
          entries.push_back(e);
        }
      if (std::none_of(entries.begin(), entries.end(), [](const auto &e) {
            return e.name == "state.bin";
          }))
        return name + "does not list state.bin";
      return "";
    }

    /**
     * Check the checkpoint in @p dir on this rank: state.bin of this
     * format, the manifest, and every file it lists present, of its size
     * and CRC32. The error ("'file' what"), empty if none.
     */
    std::string
    verify(const std::string &dir)
    {
      const std::string state = dir + "/state.bin";
      std::ifstream     in(state, std::ios::binary);
      std::string       head(magic.size(), '\0');
      if (!in)
        return "cannot open '" + state + "' (is it a checkpoint directory?)";
      in.read(head.data(), head.size());
      if (head.rfind(magic_1, 0) == 0)
        return "'" + state
               + "' is of checkpoint format 1 (an older pneuma), which has "
                 "no checksums to verify it; run again from the start";
      if (head != magic)
        return "'" + state + "' is not a pneuma checkpoint";
      std::vector<ManifestEntry> entries;
      const std::string          error = read_manifest(dir, entries);
      if (!error.empty())
        return error;
      for (const auto &e : entries)
        {
          const std::string file = dir + "/" + e.name;
          std::error_code   ec;
          const auto        size = fs::file_size(file, ec);
          if (ec)
            return "'" + file + "' is missing (the manifest lists it)";
          if (size != e.size)
            return "'" + file + "' is "
                   + (size < e.size ? "truncated" : "damaged") + " ("
                   + std::to_string(size) + " bytes, the manifest says "
                   + std::to_string(e.size) + ")";
          std::uint32_t crc = 0;
          if (!file_crc(file, crc))
            return "cannot read '" + file + "'";
          if (crc != e.crc)
            return "'" + file + "' is damaged: its CRC32 is " + hex(crc)
                   + ", the manifest says " + hex(e.crc);
        }
      return "";
    }

    /// Read a length at @p pos of @p bytes; false if it does not fit.
    bool
    read_length(const std::vector<char> &bytes,
                std::size_t             &pos,
                std::uint64_t           &value)
    {
      if (bytes.size() - pos < sizeof(value))
        return false;
      std::copy(bytes.begin() + pos,
                bytes.begin() + pos + sizeof(value),
                reinterpret_cast<char *>(&value));
      pos += sizeof(value);
      return true;
    }

    /**
     * The sections of state.bin's @p bytes (named @p file in messages);
     * every length is checked against what is left of the file.
     */
    std::string
    split_sections(const std::vector<char>                  &bytes,
                   const std::string                        &file,
                   std::map<std::string, std::vector<char>> &sections)
    {
      const std::string where = "'" + file + "' ";
      std::size_t       pos   = magic.size();
      std::uint64_t     n     = 0;
      if (bytes.size() < pos || !read_length(bytes, pos, n))
        return where + "is truncated";
      if (n > (bytes.size() - pos) / (2 * sizeof(n)))
        return where + "claims " + std::to_string(n)
               + " sections, more than its " + std::to_string(bytes.size())
               + " bytes can hold";
      for (std::uint64_t k = 0; k < n; ++k)
        {
          std::uint64_t name_length = 0, length = 0;
          if (!read_length(bytes, pos, name_length)
              || name_length > bytes.size() - pos)
            return where + "is damaged (the name of section "
                   + std::to_string(k + 1) + " runs past its end)";
          const std::string name(bytes.data() + pos, name_length);
          pos += name_length;
          if (!read_length(bytes, pos, length) || length > bytes.size() - pos)
            return where + "is damaged (section '" + name + "' claims "
                   + std::to_string(length) + " bytes, "
                   + std::to_string(bytes.size() - pos) + " are left)";
          sections[name].assign(bytes.begin() + pos,
                                bytes.begin() + pos + length);
          pos += length;
        }
      if (pos != bytes.size())
        return where + "is damaged (" + std::to_string(bytes.size() - pos)
               + " bytes after its last section)";
      return "";
    }
  } // namespace

  const std::vector<char> &
  Checkpoint::section(const std::string &name) const
  {
    const auto it = sections.find(name);
    if (it == sections.end())
      throw InputError("--restart " + path,
                       "the checkpoint has no '" + name
                         + "' (it was written by another scene or version)");
    return it->second;
  }

  void
  Checkpoint::unreadable(const std::string &name) const
  {
    throw InputError("--restart " + path,
                     "section '" + name + "' of '" + path
                       + "/state.bin' cannot be read (written by another "
                         "version?)");
  }

  void
  Checkpoint::write_state(const MPI_Comm comm) const
  {
    bool ok = true;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::ofstream out(path + "/state.bin", std::ios::binary);
        const auto    write_length = [&out](const std::uint64_t n) {
          out.write(reinterpret_cast<const char *>(&n), sizeof(n));
        };
        out.write(magic.data(), magic.size());
        write_length(sections.size());
        for (const auto &[name, bytes] : sections)
          {
            write_length(name.size());
            out.write(name.data(), name.size());
            write_length(bytes.size());
            out.write(bytes.data(), bytes.size());
          }
        out.close();
        ok = static_cast<bool>(out);
      }
    if (Utilities::MPI::min(static_cast<unsigned int>(ok), comm) == 0)
      throw WriteError(path + "/state.bin");
  }

  void
  Checkpoint::write_manifest(const MPI_Comm comm) const
  {
    bool ok = true;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::vector<std::string> names;
        std::error_code          ec;
        for (const auto &entry : fs::directory_iterator(path, ec))
          if (entry.is_regular_file(ec)
              && entry.path().filename() != "manifest")
            names.push_back(entry.path().filename().string());
        ok = !ec;
        std::sort(names.begin(), names.end());
        std::string text = manifest_header + "\n";
        for (const auto &name : names)
          {
            std::uint32_t crc  = 0;
            const auto    size = fs::file_size(path + "/" + name, ec);
            ok                 = ok && !ec && file_crc(path + "/" + name, crc);
            text += hex(crc) + " " + std::to_string(size) + " " + name + "\n";
          }
        text += "end " + hex(crc_of(text)) + "\n";
        std::ofstream out(path + "/manifest", std::ios::binary);
        out << text;
        out.close();
        ok = ok && static_cast<bool>(out);
      }
    if (Utilities::MPI::min(static_cast<unsigned int>(ok), comm) == 0)
      throw WriteError(path + "/manifest");
  }

  void
  Checkpoint::read_state(const MPI_Comm comm)
  {
    const std::string where = "--restart " + path;
    // Every rank checks the files it will read (p4est reads the mesh
    // files on every rank) before anything is restored.
    const std::string error = verify(path);
    throw_if_any(comm, error.empty() ? "" : where + ": " + error);
    std::vector<char> bytes;
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      {
        std::ifstream in(path + "/state.bin", std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in),
                     std::istreambuf_iterator<char>());
      }
    bytes = Utilities::MPI::broadcast(comm, bytes, 0);
    const std::string split =
      split_sections(bytes, path + "/state.bin", sections);
    check_input(split.empty(), where, split);
  }

  void
  CheckpointPolicy::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Checkpoint");
    prm.add_parameter("Interval steps",
                      steps,
                      "Write a checkpoint (Output/Directory/checkpoint) "
                      "every this many converged steps (0: never). A run "
                      "stopped by SIGINT or SIGTERM always writes one.",
                      Patterns::Integer(0));
    prm.add_parameter("Interval minutes",
                      interval_minutes,
                      "Also write one when this much wall time has passed "
                      "since the last (0: never).",
                      Patterns::Double(0.));
    prm.add_parameter("Stop after step",
                      stop_step,
                      "Write a checkpoint after this converged step and "
                      "stop (exit 0; continue with --restart). 0: run to "
                      "the end.",
                      Patterns::Integer(0));
    prm.leave_subsection();
  }

  void
  CheckpointPolicy::parse_parameters(ParameterHandler &prm)
  {
    check_input(std::isfinite(interval_minutes),
                "Checkpoint/Interval minutes",
                "must be finite");
    std::ostringstream text;
    prm.print_parameters(text, ParameterHandler::ShortPRM);
    used = InputLayout::from_text(text.str(), {}).entries();
  }

  void
  CheckpointPolicy::write(const std::string                       &directory,
                          const MPI_Comm                           comm,
                          const std::function<void(Checkpoint &)> &fill) const
  {
    write_checkpoint(directory, comm, [&](Checkpoint &checkpoint) {
      fill(checkpoint);
      checkpoint.put("run/parameters", used);
    });
  }

  void
  write_checkpoint(const std::string                       &directory,
                   const MPI_Comm                           comm,
                   const std::function<void(Checkpoint &)> &fill)
  {
    const bool        root  = Utilities::MPI::this_mpi_process(comm) == 0;
    const std::string fresh = directory + ".new", old = directory + ".old";
    bool              ok = true;
    if (root)
      {
        std::error_code ec;
        fs::remove_all(fresh, ec);
        ok = fs::create_directories(fresh, ec) && !ec;
      }
    if (Utilities::MPI::min(static_cast<unsigned int>(ok), comm) == 0)
      throw WriteError(fresh);
    Checkpoint checkpoint(fresh);
    fill(checkpoint);
    checkpoint.write_state(comm);
    checkpoint.write_manifest(comm);
    // The new checkpoint replaces the old one only when it is complete.
    if (root)
      {
        std::error_code ec;
        fs::remove_all(old, ec);
        if (fs::exists(directory, ec))
          fs::rename(directory, old, ec);
        fs::rename(fresh, directory, ec);
        ok = !ec;
        fs::remove_all(old, ec);
      }
    if (Utilities::MPI::min(static_cast<unsigned int>(ok), comm) == 0)
      throw WriteError(directory);
  }
} // namespace pneuma
