#include <pneuma/chambers/chamber_system.h>
#include <pneuma/core/checkpoint.h>
#include <pneuma/core/input_error.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace pneuma
{
  namespace chambers
  {
    namespace
    {
      double
      curve(const Functions::ParsedFunction<3> &f, const double t)
      {
        auto &g = const_cast<Functions::ParsedFunction<3> &>(f);
        g.set_time(t);
        return g.value(Point<3>());
      }

      const AffineConstraints<double> &
      no_constraints()
      {
        static AffineConstraints<double> none;
        return none;
      }
    } // namespace

    ChamberSystem::ChamberSystem(const ChamberParameters &parameters,
                                 const ChamberAssembler  &assembler)
      : parameters(parameters)
      , assembler(assembler)
    {
    }

    bool
    ChamberSystem::pressure_controlled(const Group &g) const
    {
      return parameters.chambers[g.leader].control == GasControl::pressure
             && !g.sealed;
    }

    double
    ChamberSystem::prescribed_amount(const Group &g) const
    {
      if (g.sealed
          || parameters.chambers[g.leader].control == GasControl::pressure)
        return g.amount;
      return curve(*parameters.chambers[g.leader].amount, time) * g.V0;
    }

    std::pair<double, double>
    ChamberSystem::gas_law(const Group &g, const double V_gas) const
    {
      const GasUpdate &law    = parameters.chambers[g.leader].gas_law;
      const double     amount = prescribed_amount(g);
      return {law.pressure(V_gas, amount, parameters.ambient_pressure, g.old),
              law.pressure_derivative(
                V_gas, amount, parameters.ambient_pressure, g.old)};
    }

    void
    ChamberSystem::group_measures(const Group                        &g,
                                  const std::vector<ChamberMeasures> &m,
                                  double                             &V,
                                  double                             &V_l,
                                  double                             &A_fs,
                                  double &wetted) const
    {
      V = V_l = A_fs = wetted = 0.;
      for (const auto c : g.members)
        {
          V += m[c].volume;
          V_l += m[c].liquid_volume;
          A_fs += m[c].free_surface_area;
          wetted += m[c].wetted_area;
        }
    }

    std::vector<ChamberLoad>
    ChamberSystem::loads(const Vector<double> &border) const
    {
      std::vector<ChamberLoad> result(parameters.chambers.size());
      for (const auto &g : groups)
        for (const auto c : g.members)
          {
            ChamberLoad &load = result[c];
            load.density      = parameters.chambers[g.leader].density;
            load.gas          = g.gas;
            if (g.gas)
              load.gas_pressure = border[g.p_index] * unknown_scale[g.p_index];
            load.liquid = g.liquid && !g.empty;
            if (g.liquid)
              load.level = border[g.h_index] * unknown_scale[g.h_index];
          }
      return result;
    }

    std::vector<ChamberLoad>
    ChamberSystem::converged_loads() const
    {
      return loads(pack());
    }

    Vector<double>
    ChamberSystem::pack() const
    {
      Vector<double> border(n_total);
      for (const auto &g : groups)
        {
          if (g.gas)
            border[g.p_index] = g.p / unknown_scale[g.p_index];
          if (g.liquid)
            border[g.h_index] = g.h / unknown_scale[g.h_index];
        }
      return border;
    }

    void
    ChamberSystem::unpack(const Vector<double> &border)
    {
      for (auto &g : groups)
        {
          if (g.gas)
            g.p = border[g.p_index] * unknown_scale[g.p_index];
          if (g.liquid)
            g.h = border[g.h_index] * unknown_scale[g.h_index];
        }
    }

    void
    ChamberSystem::setup_groups()
    {
      const unsigned int n = parameters.chambers.size();
      groups.clear();
      group_of.assign(n, 0);
      n_total = 0;
      for (unsigned int c = 0; c < n; ++c)
        {
          const auto &def = parameters.chambers[c];
          if (def.filling == Filling::connected)
            {
              const unsigned int gi = group_of[def.connected_to];
              groups[gi].members.push_back(c);
              group_of[c] = gi;
              continue;
            }
          Group g;
          g.leader  = c;
          g.members = {c};
          g.liquid  = def.has_liquid();
          g.gas     = def.has_gas();
          if (g.liquid)
            g.h_index = n_total++;
          if (g.gas)
            g.p_index = n_total++;
          group_of[c] = groups.size();
          groups.push_back(g);
        }
      unknown_scale.assign(n_total, 1.);
      residual_scale.assign(n_total, 1.);
    }

    void
    ChamberSystem::initialize(const LA::Vector &u, const double t)
    {
      const unsigned int n = parameters.chambers.size();
      setup_groups();
      time = t;

      std::vector<ChamberMeasures> m;
      assembler.assemble(u,
                         no_constraints(),
                         std::vector<ChamberLoad>(n),
                         nullptr,
                         nullptr,
                         m,
                         false);
      for (auto &g : groups)
        {
          double V, V_l, A, w;
          group_measures(g, m, V, V_l, A, w);
          g.V0 = V;
          for (const auto c : g.members)
            if (!parameters.chambers[c].open && m[c].volume <= 0.)
              throw InputError(parameters.chambers[c].path + "/Regions",
                               "the walls face into the chamber (its volume "
                               "is "
                                 + std::to_string(m[c].volume)
                                 + " m^3): flip the signs of its regions");
          if (g.liquid)
            {
              const std::string error = predict_level(g, u);
              const auto       &def   = parameters.chambers[g.leader];
              if (!error.empty())
                throw InputError(def.path
                                   + (def.liquid_control == LiquidControl::level
                                        ? "/Liquid/Level"
                                        : "/Liquid/Volume"),
                                 error.substr(error.find(':') + 2));
            }
          if (!g.gas)
            continue;
          const auto  &def   = parameters.chambers[g.leader];
          const double p_a   = parameters.ambient_pressure;
          double       V_gas = V;
          if (g.liquid && !g.empty)
            V_gas -= assembler.liquid_volume(u, g.leader, g.h).first;
          if (def.control == GasControl::pressure)
            {
              g.p      = curve(*def.pressure, t);
              g.amount = def.gas_law.amount(g.p + p_a, V_gas, p_a);
            }
          else if (def.control == GasControl::amount)
            {
              g.amount = curve(*def.amount, t) * g.V0;
              // The law itself, also for the incremental update (it has
              // no earlier state yet).
              g.p = def.gas_law.law().pressure(V_gas, g.amount, p_a) - p_a;
            }
          else
            {
              g.p      = 0.;
              g.amount = V_gas;
            }
          g.old.pressure = g.p + p_a;
          g.old.volume   = V_gas;
          g.old.amount   = g.amount;
        }
      record(u);
    }

    namespace
    {
      /**
       * The level h in (lo, hi) at which @p volume(h) = {V, dV/dh} gives
       * the @p target volume: Newton from @p h, kept inside the bracket
       * by bisection, to 1e-13 relative in the volume (converged) or a
       * bracket of 1e-14 (hi - lo) (not converged).
       */
      template <typename Volume>
      std::pair<double, bool>
      search_level(const Volume &volume,
                   const double  target,
                   double        h,
                   const double  lo,
                   const double  hi)
      {
        double a = lo, b = hi;
        for (unsigned int it = 0; it < 100; ++it)
          {
            const auto [V, A] = volume(h);
            const double f    = V - target;
            if (std::abs(f) <= 1e-13 * target)
              return {h, true};
            (f < 0. ? a : b) = h;
            double next      = (A > 0.) ? h - f / A : 0.5 * (a + b);
            if (!(next > a && next < b))
              next = 0.5 * (a + b);
            h = next;
            if (b - a <= 1e-14 * (hi - lo))
              break;
          }
        return {h, false};
      }
    } // namespace

    std::string
    ChamberSystem::predict_level(Group &g, const LA::Vector &u)
    {
      const auto  &def    = parameters.chambers[g.leader];
      const double target = curve(*def.liquid_volume, time);
      double       lo = std::numeric_limits<double>::max(), hi = -lo;
      for (const auto c : g.members)
        {
          const auto [a, b] = assembler.height_range(u, c);
          lo                = std::min(lo, a);
          hi                = std::max(hi, b);
        }
      if (def.liquid_control == LiquidControl::level)
        {
          // The level is prescribed: below the lowest wall point the
          // chamber is empty; a closed chamber cannot be filled to its top.
          const double level = curve(*def.liquid_level, time);
          g.empty            = level <= lo;
          g.h                = g.empty ? lo - 1e-9 * (hi - lo) : level;
          if (!def.open && level >= hi)
            {
              std::ostringstream msg;
              msg << def.path << ": the level " << level << " m at t = " << time
                  << " is at or above the chamber's top (" << hi << " m)";
              return msg.str();
            }
          return "";
        }
      const auto volume = [&](const double h) {
        std::pair<double, double> sum{0., 0.};
        for (const auto c : g.members)
          {
            const auto v = assembler.liquid_volume(u, c, h);
            sum.first += v.first;
            sum.second += v.second;
          }
        return sum;
      };
      if (target <= 0.)
        {
          g.empty = true;
          g.h     = lo - 1e-9 * (hi - lo);
          return "";
        }
      g.empty = false;
      // The same state, time and volume as the last search, from its
      // level (on every rank: a search is collective).
      const std::uint64_t state = assembler.state(u);
      const bool          again =
        Utilities::MPI::min(static_cast<unsigned int>(
                              g.found.valid && g.found.state == state
                              && g.found.time == time
                              && g.found.target == target && g.found.h == g.h),
                            assembler.communicator())
        > 0;
      if (again)
        return "";
      g.found.valid = false;
      // Whether the volume fits is known without V(hi) when the search
      // converges below the top (V grows with h); V(hi) is needed for an
      // open chamber's bracket, and near or at the top.
      double V_hi = 0.;
      // A tank open at its top takes any volume; a chamber closed along
      // gravity (every closed one, an open slice) holds V(top).
      const bool tank       = !assembler.closed_along_gravity(g.leader);
      const auto fits_below = [&]() -> std::string {
        V_hi = volume(hi).first;
        if (tank || V_hi * (1. - 1e-9) > target)
          return "";
        std::ostringstream msg;
        msg << def.path << ": the liquid volume " << target
            << " m^3 at t = " << time << " does not fit: the chamber holds "
            << V_hi << " m^3"
            << (def.has_gas() ? " and its gas needs room" : "");
        return msg.str();
      };
      if (tank)
        {
          V_hi = volume(hi).first;
          for (double step = std::max(hi - lo, 1e-3); V_hi < target; step *= 2.)
            {
              hi   = lo + step;
              V_hi = volume(hi).first;
            }
        }
      const auto [h, converged] = search_level(
        volume, target, (g.h > lo && g.h < hi) ? g.h : 0.5 * (lo + hi), lo, hi);
      if (!tank && (!converged || hi - h <= 1e-6 * (hi - lo)))
        {
          const std::string error = fits_below();
          if (!error.empty())
            return error;
        }
      g.h     = h;
      g.found = {state, time, target, h, converged};
      return "";
    }

    Vector<double>
    ChamberSystem::border_for(const LA::Vector              &u,
                              const double                   t,
                              const Vector<double>          &border,
                              std::vector<BorderConstraint> &constraints) const
    {
      // A copy at pseudo time t with the given border: its levels, then
      // its gas pressures.
      ChamberSystem at(*this);
      at.time = t;
      at.unpack(border);
      for (auto &g : at.groups)
        if (g.liquid)
          {
            const std::string error = at.predict_level(g, u);
            AssertThrow(error.empty(), ExcMessage(error));
          }
      std::vector<ChamberMeasures> m;
      assembler.assemble(
        u, no_constraints(), at.loads(at.pack()), nullptr, nullptr, m, false);
      for (auto &g : at.groups)
        {
          const auto &def = parameters.chambers[g.leader];
          if (!g.gas)
            continue;
          if (at.pressure_controlled(g))
            g.p = curve(*def.pressure, t);
          else if (def.control != GasControl::volume || g.sealed)
            {
              double V, V_l, A, w;
              group_measures(g, m, V, V_l, A, w);
              g.p = at.gas_law(g, V - V_l).first - parameters.ambient_pressure;
            }
          else
            {
              double V, V_l, A, w;
              group_measures(g, m, V, V_l, A, w);
              BorderConstraint c;
              c.row   = g.p_index;
              c.scale = curve(*def.volume, t) * g.V0;
              c.value = V - c.scale;
              c.unit  = unknown_scale[g.p_index];
              constraints.push_back(c);
            }
        }
      return at.pack();
    }

    std::string
    ChamberSystem::begin_step(const LA::Vector &u, const double t)
    {
      time = t;
      for (auto &g : groups)
        if (g.liquid)
          {
            const std::string error = predict_level(g, u);
            if (!error.empty())
              return error;
          }

      // Measures with vectors at the predicted levels.
      std::vector<ChamberMeasures> m;
      unknown_scale.assign(n_total, 1.);
      assembler.assemble(
        u, no_constraints(), loads(pack()), nullptr, nullptr, m, true);
      force_reference          = 0.;
      const double p_a         = parameters.ambient_pressure;
      const double g_magnitude = parameters.gravity.norm();
      for (auto &g : groups)
        {
          double V, V_l, A, w;
          group_measures(g, m, V, V_l, A, w);
          // |q| (or |q_l| for a liquid alone): force per unit pressure.
          LA::Vector q(g.gas || g.empty ? m[g.leader].q : m[g.leader].q_liquid);
          for (unsigned int k = 1; k < g.members.size(); ++k)
            q +=
              g.gas || g.empty ? m[g.members[k]].q : m[g.members[k]].q_liquid;
          const double q_norm = std::max(q.l2_norm(), 1e-300);
          const auto  &def    = parameters.chambers[g.leader];
          double       p_ref  = 0.;
          if (g.gas)
            {
              if (pressure_controlled(g))
                g.p = curve(*def.pressure, t);
              else if (def.control != GasControl::volume)
                g.p = gas_law(g, V - V_l).first - p_a;
              p_ref                    = std::max(std::abs(g.p), 1e-2 * p_a);
              unknown_scale[g.p_index] = 1e3 * p_ref;
              residual_scale[g.p_index] =
                def.control == GasControl::volume && !g.sealed
                  ? q_norm * p_ref / std::max(V, 1e-300)
                  : q_norm;
            }
          if (g.liquid)
            {
              double lo = std::numeric_limits<double>::max(), hi = -lo;
              for (const auto c : g.members)
                {
                  const auto [a, b] = assembler.height_range(u, c);
                  lo                = std::min(lo, a);
                  hi                = std::max(hi, b);
                }
              const double depth_pressure =
                def.density * g_magnitude * std::max(hi - lo, g.h - lo);
              p_ref = std::max(p_ref, depth_pressure);
              const double V_ref =
                std::max({curve(*def.liquid_volume, t), std::abs(V), 1e-300});
              unknown_scale[g.h_index] = 1.;
              // The row's residual is a volume, or with a prescribed level
              // a length: both scaled to a force. The length: the walls'
              // height range, or the level over the lowest wall point (a
              // flat bottom at the start), or 1 m if both vanish (an empty
              // chamber), so that the scale stays finite.
              double L_ref = 1.;
              if (def.liquid_control == LiquidControl::level)
                {
                  L_ref = std::max(hi - lo,
                                   std::abs(curve(*def.liquid_level, t) - lo));
                  if (!(L_ref > 0.) || !std::isfinite(L_ref))
                    L_ref = 1.;
                }
              residual_scale[g.h_index] =
                def.liquid_control == LiquidControl::level
                  ? q_norm * depth_pressure / L_ref
                  : q_norm * depth_pressure / V_ref;
            }
          force_reference += q_norm * p_ref;
        }
      return "";
    }

    void
    ChamberSystem::evaluate(const Vector<double>               &border,
                            const std::vector<ChamberMeasures> &m,
                            Vector<double>                     &residual,
                            solvers::BorderCoupling            &coupling,
                            const unsigned int                  offset) const
    {
      residual.reinit(n_total);
      for (unsigned int j = 0; j < n_total; ++j)
        {
          coupling.has_B[offset + j]          = false;
          coupling.has_C[offset + j]          = false;
          coupling.unknown_scale[offset + j]  = unknown_scale[j];
          coupling.residual_scale[offset + j] = residual_scale[j];
          for (unsigned int k = 0; k < coupling.size(); ++k)
            coupling.D(offset + j, k) = 0.;
        }
      // Rows and columns of this system in the coupling.
      const auto B = [&](const unsigned int j) -> LA::Vector & {
        return coupling.B[offset + j];
      };
      const auto C = [&](const unsigned int j) -> LA::Vector & {
        return coupling.C[offset + j];
      };
      const auto has_B = [&](const unsigned int j) {
        return coupling.has_B[offset + j];
      };
      const auto has_C = [&](const unsigned int j) {
        return coupling.has_C[offset + j];
      };
      const auto D = [&](const unsigned int j,
                         const unsigned int k) -> double & {
        return coupling.D(offset + j, offset + k);
      };
      const double p_a         = parameters.ambient_pressure;
      const double g_magnitude = parameters.gravity.norm();
      for (const auto &g : groups)
        {
          const auto &def = parameters.chambers[g.leader];
          double      V, V_l, A_fs, w;
          group_measures(g, m, V, V_l, A_fs, w);
          // Group vectors q and q_l.
          // Copies of the leader's vectors (an assignment to an empty
          // vector would plan a transfer between their maps, collectively).
          LA::Vector q = g.gas ? m[g.leader].q : LA::Vector();
          if (g.gas)
            {
              for (unsigned int k = 1; k < g.members.size(); ++k)
                q += m[g.members[k]].q;
            }
          const bool with_liquid = g.liquid && !g.empty;
          LA::Vector q_l = with_liquid ? m[g.leader].q_liquid : LA::Vector();
          if (with_liquid)
            {
              for (unsigned int k = 1; k < g.members.size(); ++k)
                q_l += m[g.members[k]].q_liquid;
            }

          if (g.gas)
            {
              const unsigned int j = g.p_index;
              const double       p = border[j] * unknown_scale[j];
              B(j)                 = q;
              B(j) *= -1.;
              has_B(j) = true;
              double r = 0.;
              if (pressure_controlled(g))
                {
                  r       = p - curve(*def.pressure, time);
                  D(j, j) = 1.;
                }
              else if (def.control == GasControl::volume && !g.sealed)
                {
                  r        = V - curve(*def.volume, time) * g.V0;
                  C(j)     = q;
                  has_C(j) = true;
                }
              else
                {
                  const auto [p_abs, dp] = gas_law(g, V - V_l);
                  r                      = p - (p_abs - p_a);
                  C(j)                   = q;
                  if (with_liquid)
                    C(j) -= q_l;
                  C(j) *= -dp;
                  has_C(j) = true;
                  D(j, j)  = 1.;
                  if (with_liquid)
                    D(j, g.h_index) = dp * A_fs;
                }
              residual[j] = r * residual_scale[j];
            }
          if (g.liquid)
            {
              const unsigned int j = g.h_index;
              if (!with_liquid)
                {
                  D(j, j)     = 1.;
                  residual[j] = 0.;
                  continue;
                }
              B(j) = q_l;
              B(j) *= -def.density * g_magnitude;
              has_B(j) = true;
              if (def.liquid_control == LiquidControl::level)
                {
                  // h - h(t) = 0: a row of its own (the border solve
                  // eliminates it first).
                  D(j, j)     = 1.;
                  residual[j] = (border[j] * unknown_scale[j]
                                 - curve(*def.liquid_level, time))
                                * residual_scale[j];
                  continue;
                }
              C(j)     = q_l;
              has_C(j) = true;
              D(j, j)  = A_fs;
              residual[j] =
                (V_l - curve(*def.liquid_volume, time)) * residual_scale[j];
            }
        }
    }

    void
    ChamberSystem::commit_step(const LA::Vector         &u,
                               const double              t,
                               const ConditionalOStream &out)
    {
      const double p_a = parameters.ambient_pressure;
      record(u);
      for (auto &g : groups)
        {
          if (!g.gas)
            continue;
          const auto &def   = parameters.chambers[g.leader];
          double      V_gas = 0.;
          for (const auto c : g.members)
            V_gas += chamber_reports[c].gas_volume;
          if (pressure_controlled(g) && def.seal_time >= 0.
              && t >= def.seal_time - 1e-12)
            {
              g.sealed = true;
              g.amount = def.gas_law.amount(g.p + p_a, V_gas, p_a);
              out << "  " << def.path << " sealed at t = " << t
                  << ": p = " << g.p << " Pa gauge, gas volume " << V_gas
                  << " m^3, amount " << g.amount << " m^3 at ambient pressure"
                  << std::endl;
            }
          else if (!g.sealed && def.control != GasControl::amount)
            g.amount = def.gas_law.amount(g.p + p_a, V_gas, p_a);
          else if (!g.sealed)
            g.amount = prescribed_amount(g);
          g.old.pressure = g.p + p_a;
          g.old.volume   = V_gas;
          g.old.amount   = g.amount;
          // Only the amount changed since record(): no second assembly.
          for (const auto c : g.members)
            chamber_reports[c].gas_amount = g.amount;
        }
    }

    void
    ChamberSystem::save_checkpoint(Checkpoint &checkpoint) const
    {
      std::vector<std::vector<double>> state;
      for (const auto &g : groups)
        state.push_back({g.p,
                         g.h,
                         g.V0,
                         g.amount,
                         g.sealed ? 1. : 0.,
                         g.empty ? 1. : 0.,
                         g.old.pressure,
                         g.old.volume,
                         g.old.amount});
      checkpoint.put("chambers/groups", state);
      // The scales of the border unknowns of the step (begin_step()): the
      // model's border in the checkpoint is in these units.
      checkpoint.put("chambers/unknown_scale", unknown_scale);
    }

    void
    ChamberSystem::load_checkpoint(const Checkpoint &checkpoint)
    {
      const auto state =
        checkpoint.get<std::vector<std::vector<double>>>("chambers/groups");
      check_input(state.size() == groups.size(),
                  "--restart " + checkpoint.directory(),
                  "the checkpoint has " + std::to_string(state.size())
                    + " chamber groups, the input "
                    + std::to_string(groups.size()));
      for (unsigned int k = 0; k < groups.size(); ++k)
        {
          auto       &g = groups[k];
          const auto &s = state[k];
          g.p           = s[0];
          g.h           = s[1];
          g.V0          = s[2];
          g.amount      = s[3];
          g.sealed      = s[4] != 0.;
          g.empty       = s[5] != 0.;
          g.old         = GasState{s[6], s[7], s[8]};
        }
      const auto scale =
        checkpoint.get<std::vector<double>>("chambers/unknown_scale");
      check_input(scale.size() == unknown_scale.size(),
                  "--restart " + checkpoint.directory(),
                  "the checkpoint has " + std::to_string(scale.size())
                    + " chamber unknowns, the input "
                    + std::to_string(unknown_scale.size()));
      unknown_scale = scale;
    }

    void
    ChamberSystem::record(const LA::Vector &u)
    {
      const unsigned int           n = parameters.chambers.size();
      std::vector<ChamberMeasures> m;
      assembler.assemble(
        u, no_constraints(), converged_loads(), nullptr, nullptr, m, false);
      chamber_reports.assign(n, ChamberReport());
      const double p_a = parameters.ambient_pressure;
      for (const auto &g : groups)
        {
          double V_gas_group = 0.;
          for (const auto c : g.members)
            V_gas_group += m[c].volume - m[c].liquid_volume;
          const auto &def = parameters.chambers[g.leader];
          for (const auto c : g.members)
            {
              ChamberReport &r = chamber_reports[c];
              r.volume = assembler.closed_along_gravity(c) ? m[c].volume : 0.;
              r.liquid_volume = m[c].liquid_volume;
              r.gas_volume    = g.gas ? m[c].volume - m[c].liquid_volume : 0.;
              r.wetted_area   = m[c].wetted_area;
              if (g.liquid)
                r.level = g.h;
              if (g.gas)
                {
                  r.pressure          = g.p;
                  r.absolute_pressure = g.p + p_a;
                  r.gas_amount        = g.amount;
                  r.pv_kappa          = def.gas_law.law().invariant(
                    {r.absolute_pressure, V_gas_group, g.amount});
                }
            }
        }
    }
  } // namespace chambers
} // namespace pneuma
