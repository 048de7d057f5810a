package tactus.engine;

/**
 * Builds a {@link StepPlan} from the mass and link tables. Masses are laid out grouped by
 * kind (in {@link MassKind} order, insertion order within a kind) and links become one batch
 * per kind present. The live state of masses and links that were already in the previous
 * plan is carried over exactly; new masses start from their pending state and new links
 * take their previous distance from the current positions.
 */
final class PlanCompiler {
    private PlanCompiler() {
    }

    static StepPlan compile(MassTable mt, LinkTable lt, Medium medium, StepPlan old, boolean stencils,
                            boolean sweeps, java.util.List<ContactGroupSpec> groups) {
        int[] start = kindStarts(mt, mt.count);
        int n = start[start.length - 1];
        int[] newSlot = slotsByKind(mt, mt.count, start);
        LinkBatch[] batches = buildBatches(lt, newSlot, stencils, true);
        StepPlan p = new StepPlan(n, start, batches, medium);
        for (int id = 0; id < mt.count; id++) {
            int s = newSlot[id];
            if (s < 0) {
                continue;
            }
            p.massId[s] = id;
            int o = mt.slot[id];
            if (old != null && o >= 0) {
                copyState(old, o, p, s);
            } else {
                startFromPending(mt, id, p, s);
            }
            fillMass(p, s, mt, id, medium);
        }
        System.arraycopy(newSlot, 0, mt.slot, 0, mt.count);
        fillLinks(lt, p, old);
        p.groups = buildGroups(groups, mt, newSlot, p);
        p.sweepRuns = sweeps;
        p.selectKernels();
        return p;
    }

    /**
     * The first half of a compile, without side effects on the tables or the old plan: lays out the masses and
     * builds the link batches, stencil runs, contact groups and kernels of the new plan, but leaves its state and
     * coefficients unset. Safe to run on another thread while the owner steps the old plan, as long as no other
     * thread changes the topology meanwhile (the caller checks that before {@link #install}).
     *
     * @return the new plan, whose {@code massId} is set; its mass slots by id come with it
     */
    static Prepared prepare(MassTable mt, LinkTable lt, Medium medium, boolean stencils, boolean sweeps,
                            java.util.List<ContactGroupSpec> groups) {
        int count = mt.count;
        int[] start = kindStarts(mt, count);
        int n = start[start.length - 1];
        int[] newSlot = slotsByKind(mt, count, start);
        LinkBatch[] batches = buildBatches(lt, newSlot, stencils, false);
        StepPlan p = new StepPlan(n, start, batches, medium);
        for (int id = 0; id < count; id++) {
            if (newSlot[id] >= 0) {
                p.massId[newSlot[id]] = id;
            }
        }
        p.groups = buildGroups(groups, mt, newSlot, p);
        p.sweepRuns = sweeps;
        p.selectKernels();
        return new Prepared(p, newSlot, lt.count);
    }

    /**
     * The second half of a compile, run by the thread that steps the model between two steps: copies the live
     * state of carried-over masses and links from the old plan (as it is now), starts new masses from their
     * pending state (consuming their pending forces), writes every coefficient from the current parameters, and
     * rewrites the slot mappings of the tables. O(masses + links) copies, no allocation. Gives the same plan, bit
     * for bit, as {@link #compile} would at this point.
     */
    static StepPlan install(MassTable mt, LinkTable lt, Medium medium, StepPlan old, Prepared prep) {
        StepPlan p = prep.plan;
        for (int s = 0; s < p.nMass; s++) {
            int id = p.massId[s];
            int o = mt.slot[id];
            if (old != null && o >= 0) {
                copyState(old, o, p, s);
            } else {
                startFromPending(mt, id, p, s);
            }
            fillMass(p, s, mt, id, medium);
        }
        System.arraycopy(prep.massSlot, 0, mt.slot, 0, prep.massSlot.length);
        for (int id = 0; id < prep.linkCount; id++) {
            if (!lt.alive[id]) {
                lt.slot[id] = -1;
            }
        }
        fillLinks(lt, p, old);
        return p;
    }

    /** A plan built by {@link #prepare}, waiting for {@link #install}. */
    static final class Prepared {
        final StepPlan plan;
        final int[] massSlot;
        final int linkCount;

        Prepared(StepPlan plan, int[] massSlot, int linkCount) {
            this.plan = plan;
            this.massSlot = massSlot;
            this.linkCount = linkCount;
        }
    }

    private static void startFromPending(MassTable mt, int id, StepPlan p, int s) {
        int q = 6 * id;
        p.x[s] = mt.pending[q];
        p.y[s] = mt.pending[q + 1];
        p.z[s] = mt.pending[q + 2];
        p.px[s] = mt.pending[q + 3];
        p.py[s] = mt.pending[q + 4];
        p.pz[s] = mt.pending[q + 5];
        int f = 3 * id;
        p.fx[s] = mt.pendingForce[f];
        p.fy[s] = mt.pendingForce[f + 1];
        p.fz[s] = mt.pendingForce[f + 2];
        mt.pendingForce[f] = 0;
        mt.pendingForce[f + 1] = 0;
        mt.pendingForce[f + 2] = 0;
        boolean target = !Double.isNaN(mt.pendingTarget[f]);
        p.tx[s] = target ? mt.pendingTarget[f] : p.x[s];
        p.ty[s] = target ? mt.pendingTarget[f + 1] : p.y[s];
        p.tz[s] = target ? mt.pendingTarget[f + 2] : p.z[s];
    }

    private static ContactGroupKernel[] buildGroups(java.util.List<ContactGroupSpec> groups, MassTable mt,
                                                    int[] slot, StepPlan p) {
        java.util.ArrayList<ContactGroupKernel> out = new java.util.ArrayList<>();
        for (ContactGroupSpec g : groups) {
            if (!g.alive) {
                continue;
            }
            int[] slots = new int[g.members.length];
            int n = 0;
            for (int id : g.members) {
                if (mt.isLive(id)) {
                    slots[n++] = slot[id];
                }
            }
            out.add(new ContactGroupKernel(p, java.util.Arrays.copyOf(slots, n), g.threshold, g.stiffness,
                    g.damping, ContactGroupSpec.SKIN * g.threshold));
        }
        return out.toArray(new ContactGroupKernel[0]);
    }

    private static void copyState(StepPlan from, int o, StepPlan to, int s) {
        to.x[s] = from.x[o];
        to.y[s] = from.y[o];
        to.z[s] = from.z[o];
        to.px[s] = from.px[o];
        to.py[s] = from.py[o];
        to.pz[s] = from.pz[o];
        to.fx[s] = from.fx[o];
        to.fy[s] = from.fy[o];
        to.fz[s] = from.fz[o];
        to.tx[s] = from.tx[o];
        to.ty[s] = from.ty[o];
        to.tz[s] = from.tz[o];
    }

    /** Writes the per-slot coefficients of one mass from its parameters and the medium. */
    static void fillMass(StepPlan p, int s, MassTable mt, int id, Medium medium) {
        p.massParamsVersion++;
        MassKind k = mt.kind[id];
        double im = k.isInertial() ? 1.0 / mt.mass[id] : 0.0;
        p.invM[s] = im;
        p.inputWeight[s] = k.isInput() ? mt.weight[id] : 0.0;
        if (k.isOscillator()) {
            p.retention[s] = 1.0 - (mt.damping[id] + medium.friction) * im;
            p.oscStiffnessPerMass[s] = mt.stiffness[id] * im;
            p.restX[s] = mt.rest[3 * id];
            p.restY[s] = mt.rest[3 * id + 1];
            p.restZ[s] = mt.rest[3 * id + 2];
        } else {
            p.retention[s] = k == MassKind.MASS3D_SIMPLE ? 1.0 : 1.0 - medium.friction * im;
            p.oscStiffnessPerMass[s] = 0.0;
        }
        if (k == MassKind.DRIVEN3D) {
            p.tx[s] = mt.drive[3 * id];
            p.ty[s] = mt.drive[3 * id + 1];
            p.tz[s] = mt.drive[3 * id + 2];
        }
        if (k.isFixed()) {
            p.px[s] = p.x[s];
            p.py[s] = p.y[s];
            p.pz[s] = p.z[s];
        }
    }

    private static LinkBatch[] buildBatches(LinkTable lt, int[] massSlot, boolean stencils, boolean writeSlots) {
        LinkKind[] kinds = LinkKind.values();
        int[] counts = new int[kinds.length];
        for (int id = 0; id < lt.count; id++) {
            if (lt.alive[id]) {
                counts[lt.kind[id].ordinal()]++;
            }
        }
        LinkBatch[] batches = new LinkBatch[kinds.length];
        for (LinkKind k : kinds) {
            if (counts[k.ordinal()] > 0) {
                batches[k.ordinal()] = new LinkBatch(k, counts[k.ordinal()]);
            }
        }
        LinkBatch plane = batches[LinkKind.PLANE_CONTACT3D.ordinal()];
        int[] planeCursor = new int[3];
        if (plane != null) {
            int[] perAxis = new int[3];
            for (int id = 0; id < lt.count; id++) {
                if (lt.alive[id] && lt.kind[id] == LinkKind.PLANE_CONTACT3D) {
                    perAxis[lt.axis[id]]++;
                }
            }
            plane.axisStart[1] = perAxis[0];
            plane.axisStart[2] = perAxis[0] + perAxis[1];
            plane.axisStart[3] = plane.n;
            planeCursor[0] = 0;
            planeCursor[1] = plane.axisStart[1];
            planeCursor[2] = plane.axisStart[2];
        }
        int[] cursor = new int[kinds.length];
        for (int id = 0; id < lt.count; id++) {
            if (!lt.alive[id]) {
                if (writeSlots) {
                    lt.slot[id] = -1;
                }
                continue;
            }
            LinkKind k = lt.kind[id];
            LinkBatch b = batches[k.ordinal()];
            int j = k == LinkKind.PLANE_CONTACT3D ? planeCursor[lt.axis[id]]++ : cursor[k.ordinal()]++;
            b.id[j] = id;
            b.a[j] = massSlot[lt.a[id]];
            b.b[j] = k.isSingleMass() ? b.a[j] : massSlot[lt.b[id]];
        }
        for (LinkKind k : kinds) {
            LinkBatch b = batches[k.ordinal()];
            if (b != null && stencils && StencilPlanner.eligible(k)) {
                batches[k.ordinal()] = StencilPlanner.organize(b);
            }
        }
        return batches;
    }

    private static void fillLinks(LinkTable lt, StepPlan p, StepPlan old) {
        for (LinkBatch b : p.batches) {
            if (b == null) {
                continue;
            }
            for (int j = 0; j < b.n; j++) {
                int id = b.id[j];
                fillLink(b, j, lt, id);
                int o = lt.slot[id];
                if (old != null && o >= 0 && old.batches[b.kind.ordinal()] != null) {
                    b.setPrev(j, old.batches[b.kind.ordinal()].prev(o));
                } else {
                    b.setPrev(j, freshPrevious(b, j, p));
                }
            }
            for (int j = 0; j < b.n; j++) {
                lt.slot[b.id[j]] = j;
            }
        }
    }

    /** Writes the parameters of one link into its batch slot. */
    static void fillLink(LinkBatch b, int j, LinkTable lt, int id) {
        b.setParams(j, lt.stiffness[id], lt.damping[id], lt.length[id], lt.planePosition[id], lt.attraction[id],
                lt.aux0[id], lt.aux1[id]);
    }

    /**
     * @return the damper's previous distance for link slot j starting afresh: the current distance for a
     *     tracked link (no velocity), or the inactive mark -1 for a conditional one
     */
    private static double freshPrevious(LinkBatch b, int j, StepPlan p) {
        return b.kind.isConditional() ? -1.0 : distanceOf(b, j, p);
    }

    /**
     * Makes links forget the distance they saw before, so that their dampers do not mistake a jump (a mass
     * moved by hand, a repaired divergence) for a velocity: tracked links take the current distance as their
     * previous one, and conditional links (contacts, ropes, bubbles) start again as inactive. Plane contacts
     * and attractors keep no previous distance.
     *
     * @param slot the mass slot whose links are reset, or -1 for every link
     */
    static void resetLinkHistory(StepPlan p, int slot) {
        for (LinkBatch b : p.batches) {
            if (b == null || !b.kind.keepsHistory()) {
                continue;
            }
            for (int j = 0; j < b.n; j++) {
                if (slot < 0 || b.a[j] == slot || b.b[j] == slot) {
                    b.setPrev(j, freshPrevious(b, j, p));
                }
            }
        }
    }

    /** @return the current distance of link slot j (the signed z difference for a 1-D kind). */
    static double distanceOf(LinkBatch b, int j, StepPlan p) {
        int a = b.a[j], c = b.b[j];
        if (b.kind.isOneDimensional()) {
            return p.z[a] - p.z[c];
        }
        double dx = p.x[a] - p.x[c], dy = p.y[a] - p.y[c], dz = p.z[a] - p.z[c];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /** @return where each mass kind starts in the plan's layout (kinds in MassKind order), and the total last. */
    private static int[] kindStarts(MassTable mt, int count) {
        int kinds = MassKind.values().length;
        int[] counts = new int[kinds];
        for (int id = 0; id < count; id++) {
            if (mt.alive[id]) {
                counts[mt.kind[id].ordinal()]++;
            }
        }
        int[] start = new int[kinds + 1];
        for (int k = 0; k < kinds; k++) {
            start[k + 1] = start[k] + counts[k];
        }
        return start;
    }

    /** @return each mass id's slot in the plan (grouped by kind, insertion order within a kind), -1 if removed. */
    private static int[] slotsByKind(MassTable mt, int count, int[] start) {
        int[] cursor = start.clone();
        int[] slot = new int[count];
        for (int id = 0; id < count; id++) {
            slot[id] = mt.alive[id] ? cursor[mt.kind[id].ordinal()]++ : -1;
        }
        return slot;
    }
}
