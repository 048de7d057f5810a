package tactus.export;

import static tactus.export.FaustNumbers.lit;

import tactus.linkModuleType;
import tactus.matModuleType;

/**
 * Writes a 1-D model with the primitives of Faust's {@code mi.lib} (the mass-interaction library by the paper's
 * first author), one primitive per module, on the z coordinate:
 * <ul>
 * <li>{@code Mass1D}: {@code mi.mass(M, grav, z0, zr0)}, or with air friction f {@code mi.oscil(M, 0, f, ...)}
 * (mi.mass has no friction; mi.oscil with no stiffness is exactly Tactus's mass with retention 1 - f/M);</li>
 * <li>{@code Osc1D}: {@code mi.oscil(M, K, Z + f, grav, z0 - r, zr0 - r) : +(r)}: mi.oscil's spring pulls toward 0,
 * Tactus's toward the rest point r, so the oscillator runs in coordinates relative to r;</li>
 * <li>{@code Ground1D}: {@code mi.ground(z0)};</li>
 * <li>{@code SpringDamper1D}: {@code mi.springDamper(K, Z, ...)} ({@code mi.spring} without damping), with the rest
 * length subtracted from mass 1's position first (mi.lib's springs have none);</li>
 * <li>mi.lib's nonlinear interactions in 1-D ({@code QuadraticSpringDamper1D}, {@code CubicSpringDamper1D},
 * {@code ClippedSpringDamper1D}, {@code Pluck1D}, {@code Bow1D}, {@code ClippedContact1D}): the mi.lib function
 * their descriptor names ({@code mi.nlSpringDamper2}, ...), with the arguments in mi.lib's order;</li>
 * <li>{@code Contact3D} between two masses on the same vertical line: {@code mi.collision(K, Z, r, ...)} with the
 * lower mass first; {@code PlaneContact3D} across z: {@code mi.collision} against the plane's coordinate.</li>
 * </ul>
 * mi.lib's gravity is a force subtracted from the input, Tactus's an acceleration: grav = -g_z M. Its dampers
 * compute {@code (x1 - x1') : initState(x1r0)}, so the "initial delayed position" x1r0 is added to the first
 * sample's velocity: to start a damper from rest it is minus the current position.
 */
final class MiLibWriter {
    private MiLibWriter() {
    }

    /** @return null when the scene fits mi.lib, else why not (the first module that does not) */
    static String whyNot(Scene s) {
        for (Scene.MassRow m : s.masses) {
            if (m.type != matModuleType.Mass1D && m.type != matModuleType.Osc1D && m.type != matModuleType.Ground1D) {
                return m.type + " \"" + m.name + "\"";
            }
        }
        for (Scene.LinkRow l : s.links) {
            if (l.type == linkModuleType.SpringDamper1D || l.type == linkModuleType.PlaneContact3D
                    || (l.type.isNonlinear() && l.type.isOneDimensional())) {
                continue;
            }
            if (l.type == linkModuleType.Contact3D) {
                Scene.MassRow a = s.masses[l.a];
                Scene.MassRow b = s.masses[l.b];
                if (a.x0[0] == b.x0[0] && a.x0[1] == b.x0[1] && a.x0[2] != b.x0[2]) {
                    continue;
                }
            }
            return l.type + " \"" + l.name + "\"";
        }
        return null;
    }

    static void build(Scene s, Params p, FaustExportOptions o, Network net) {
        int[] pos = new int[s.masses.length];
        int[] port = new int[s.masses.length];
        for (int i = 0; i < s.masses.length; i++) {
            Scene.MassRow m = s.masses[i];
            port[i] = net.addPort();
            pos[i] = net.addMass(massBlock(s, p, i), 1);
            if (m.type != matModuleType.Ground1D) {
                net.addPending(port[i], m.f0[2]);
            }
        }
        for (int j = 0; j < s.links.length; j++) {
            Scene.LinkRow l = s.links[j];
            if (l.type == linkModuleType.SpringDamper1D) {
                Scene.MassRow a = s.masses[l.a];
                Scene.MassRow b = s.masses[l.b];
                boolean rest = l.l0 != 0 || p.linkSlid[j];
                boolean damped = l.z != 0 || p.linkSlid[j];
                // mi.lib adds x1r0 to the first sample's velocity (x1 - x1' : initState(x1r0)): minus the position
                String za = rest ? sub(p.linkL[j], lit(a.x0[2])) : lit(-a.x0[2]);
                String block = damped
                        ? "mi.springDamper(" + p.linkK[j] + ", " + p.linkZ[j] + ", " + za + ", " + lit(-b.x0[2]) + ")"
                        : "mi.spring(" + p.linkK[j] + ", " + za + ", " + lit(-b.x0[2]) + ")";
                if (rest) {
                    block = "(-(" + p.linkL[j] + "), _) : " + block;
                }
                net.addLink(block, new int[] {pos[l.a], pos[l.b]}, new int[] {port[l.a], port[l.b]});
            } else if (l.type.isNonlinear()) {
                net.addLink(nonlinearBlock(s, p, j), new int[] {pos[l.a], pos[l.b]},
                        new int[] {port[l.a], port[l.b]});
            } else if (l.type == linkModuleType.Contact3D) {
                boolean aLow = s.masses[l.a].x0[2] < s.masses[l.b].x0[2];
                int lo = aLow ? l.a : l.b;
                int hi = aLow ? l.b : l.a;
                String block = "mi.collision(" + p.linkK[j] + ", " + p.linkZ[j] + ", " + p.linkL[j] + ", "
                        + neg(add(lit(s.masses[lo].x0[2]), p.linkL[j])) + ", " + lit(-s.masses[hi].x0[2]) + ")";
                net.addLink(block, new int[] {pos[lo], pos[hi]}, new int[] {port[lo], port[hi]});
            } else if (l.axis == 2) {
                String block = "(" + lit(l.planePos) + ", _) : mi.collision(" + p.linkK[j] + ", " + p.linkZ[j] + ", "
                        + p.linkL[j] + ", " + neg(add(lit(l.planePos), p.linkL[j])) + ", "
                        + lit(-s.masses[l.a].x0[2]) + ") : (!, _)";
                net.addLink(block, new int[] {pos[l.a]}, new int[] {port[l.a]});
            }
            // a plane across x or y pushes a 1-D mass along an axis it cannot move on: nothing to write
        }
        for (FaustExportOptions.Listen li : o.listens()) {
            int i = s.mass(li.mass);
            if (li.axis != 2) {
                net.addOutput(-1, 0, li.gain);
            } else {
                net.addOutput(pos[i], s.masses[i].x0[2], li.gain);
            }
        }
        for (FaustExportOptions.Input in : o.inputs()) {
            int i = s.mass(in.mass);
            boolean moves = in.axis == 2 && s.masses[i].type != matModuleType.Ground1D;
            net.addInput(moves ? port[i] : -1, s.forceScale());
        }
    }

    /**
     * One of mi.lib's nonlinear interactions, written from its descriptor: the function and its arguments in mi.lib's
     * order, then the initial delayed positions. A kind with a rest length has it subtracted from mass 1's position
     * first, as for the linear spring; a collision adds its threshold to mass 1's position inside mi.lib, so its
     * first delayed position is minus mass 1's position plus the threshold.
     */
    private static String nonlinearBlock(Scene s, Params p, int j) {
        Scene.LinkRow l = s.links[j];
        boolean collision = l.type.miLibFunction().startsWith("nlCollision");
        boolean rest = !collision && l.l0 != 0;
        StringBuilder b = new StringBuilder(call(l, p, j));
        double xa = s.masses[l.a].x0[2];
        String za = collision ? neg(add(lit(xa), p.linkL[j])) : rest ? sub(p.linkL[j], lit(xa)) : lit(-xa);
        b.append(za).append(", ").append(lit(-s.masses[l.b].x0[2])).append(')');
        return rest ? "(-(" + p.linkL[j] + "), _) : " + b : b.toString();
    }

    /**
     * @return the start of a call of the kind's mi.lib function, {@code "mi.nlPluck(K, scale, Z, "}, its arguments in
     *     mi.lib's order as the descriptor names them, ready for the two initial delayed positions
     */
    static String call(Scene.LinkRow l, Params p, int j) {
        String[] extraNames = l.type.extraParameterNames();
        StringBuilder b = new StringBuilder("mi.").append(l.type.miLibFunction()).append('(');
        for (String arg : l.type.miLibArguments()) {
            switch (arg) {
                case "K":
                    b.append(p.linkK[j]);
                    break;
                case "Z":
                    b.append(p.linkZ[j]);
                    break;
                case "dist":
                    b.append(p.linkL[j]);
                    break;
                default:
                    b.append(lit(l.extra[java.util.Arrays.asList(extraNames).indexOf(arg)]));
            }
            b.append(", ");
        }
        return b.toString();
    }

    private static String massBlock(Scene s, Params p, int i) {
        Scene.MassRow m = s.masses[i];
        String mm = p.massM[i];
        String grav = s.g[2] == 0 ? "0.0" : lit(-s.g[2]) + "*" + mm;
        String z0 = lit(m.x0[2]);
        String zr0 = lit(m.xr0[2]);
        switch (m.type) {
            case Ground1D:
                return "mi.ground(" + z0 + ")";
            case Osc1D: {
                double r = m.rest[2];
                String damping = s.friction == 0 ? p.massZ[i] : add(p.massZ[i], lit(s.friction));
                String block = "mi.oscil(" + mm + ", " + p.massK[i] + ", " + damping + ", " + grav + ", "
                        + lit(m.x0[2] - r) + ", " + lit(m.xr0[2] - r) + ")";
                return r == 0 ? block : "(" + block + " : +(" + lit(r) + "))";
            }
            default:
                if (s.friction == 0) {
                    return "mi.mass(" + mm + ", " + grav + ", " + z0 + ", " + zr0 + ")";
                }
                return "mi.oscil(" + mm + ", 0.0, " + lit(s.friction) + ", " + grav + ", " + z0 + ", " + zr0 + ")";
        }
    }

    private static String add(String a, String b) {
        return "(" + a + " + " + b + ")";
    }

    private static String neg(String a) {
        return "(0 - " + a + ")";
    }

    private static String sub(String a, String b) {
        return "(" + a + " - " + b + ")";
    }
}
