package tactus.engine;

/**
 * A compiled scene: the state of every mass as flat arrays grouped by kind, the links as
 * one flat batch per kind, and the list of kernels that this scene needs, in order
 * (masses first, then interactions). A plan is rebuilt when the topology changes and its
 * kernel list is re-selected when a global effect (gravity, friction) is switched on or off.
 *
 * <p>Stepping a plan allocates nothing.
 */
public final class StepPlan {
    final int nMass;
    final double[] x;
    final double[] y;
    final double[] z;
    final double[] px;
    final double[] py;
    final double[] pz;
    final double[] fx;
    final double[] fy;
    final double[] fz;
    /** 1/M for inertial masses, 0 otherwise. */
    final double[] invM;
    /** Velocity retention per step: 1 - f/M (masses) or 1 - (Z + f)/M (oscillators). */
    final double[] retention;
    /** K/M of oscillators. */
    final double[] oscStiffnessPerMass;
    /** Rest position of oscillators. */
    final double[] restX;
    final double[] restY;
    final double[] restZ;
    /** EWMA weight of input modules. */
    final double[] inputWeight;
    /** Target position of input modules. */
    final double[] tx;
    final double[] ty;
    final double[] tz;
    /** Masses of kind k occupy slots [kindStart[k], kindStart[k + 1]). */
    final int[] kindStart;
    /** Stable id of the mass in each slot. */
    final int[] massId;
    /** One batch per link kind (by ordinal), null when the scene has none of that kind. */
    final LinkBatch[] batches;
    final Medium medium;
    /*
     * Scratch arrays (one value per mass slot) shared by the stencil-run kernels; null when there are no runs.
     * For the link whose near end is slot i: stencilVec holds the far end's position, then the difference
     * X(i) - X(i + o), then the force on the near end; stencilDist the distance, then the scalar force over the
     * distance. stencilFar holds, at the far end's slot i + o, the force of the link to subtract there.
     */
    double[] stencilVecX;
    double[] stencilVecY;
    double[] stencilVecZ;
    double[] stencilDist;
    double[] stencilFarX;
    double[] stencilFarY;
    double[] stencilFarZ;
    /** Contact groups (broad-phase contacts), run right after the explicit Contact3D links. */
    ContactGroupKernel[] groups = new ContactGroupKernel[0];
    /**
     * true (the default): stencil runs are stepped in one sweep, and chains move their own masses
     * ({@link #selectKernels()}); false: masses by their own kernels, then every run in two passes.
     */
    boolean sweepRuns = true;
    /**
     * true when some interaction kernel (a 3-D link, a plane contact, a contact group) may write an x or y force
     * into a one-dimensional mass (Mass1D, Osc1D), whose own kernels then clear those forces every step; false
     * (the usual case) when nothing but the API can write them there, so that the 1-D kernels leave them alone
     * (two stores per mass and step fewer) and {@link #settleOffAxisForces()} clears what the API wrote.
     */
    boolean offAxisWriters;
    /**
     * Set when an x or y force may have been written into a one-dimensional mass outside the kernels (the API's
     * {@code addForce}, a compile that carried forces over); cleared by {@link #settleOffAxisForces()}.
     */
    boolean offAxisResidue = true;
    /**
     * Counts changes of the masses' coefficients ({@link PlanCompiler#fillMass}): the oscillator kernels look again
     * whether their masses share one retention and one stiffness ({@link #prepareStep()}).
     */
    int massParamsVersion;
    /** The {@link #massParamsVersion} the oscillator kernels last looked at. */
    private int seenMassParams = -1;
    private Kernel[] kernels = new Kernel[0];
    private int kernelsVersion;

    StepPlan(int nMass, int[] kindStart, LinkBatch[] batches, Medium medium) {
        this.nMass = nMass;
        x = new double[nMass];
        y = new double[nMass];
        z = new double[nMass];
        px = new double[nMass];
        py = new double[nMass];
        pz = new double[nMass];
        fx = new double[nMass];
        fy = new double[nMass];
        fz = new double[nMass];
        invM = new double[nMass];
        retention = new double[nMass];
        oscStiffnessPerMass = new double[nMass];
        restX = new double[nMass];
        restY = new double[nMass];
        restZ = new double[nMass];
        inputWeight = new double[nMass];
        tx = new double[nMass];
        ty = new double[nMass];
        tz = new double[nMass];
        massId = new int[nMass];
        this.kindStart = kindStart;
        this.batches = batches;
        this.medium = medium;
    }

    /**
     * Runs one simulation step: every mass kernel, then every interaction kernel. Package-private: stepping
     * goes through {@link Engine#step(int)}, which counts steps and runs the divergence guard.
     */
    void step() {
        prepareStep();
        Kernel[] ks = kernels;
        for (int i = 0; i < ks.length; i++) {
            ks[i].run();
        }
    }

    Kernel[] kernels() {
        return kernels;
    }

    /**
     * What must hold before the kernels run, on the thread that steps (before a parallel batch, on the thread that
     * starts it): the x and y forces of the 1-D masses settled ({@link #settleOffAxisForces()}) and, after a change
     * of the masses' coefficients, the oscillator kernels' shared coefficients looked at again. Allocates nothing.
     */
    void prepareStep() {
        settleOffAxisForces();
        if (massParamsVersion != seenMassParams) {
            seenMassParams = massParamsVersion;
            for (Kernel k : kernels) {
                MassKernels.SlotKernel m = k instanceof StencilKernel ? ((StencilKernel) k).masses()
                        : k instanceof MassKernels.SlotKernel ? (MassKernels.SlotKernel) k : null;
                if (m instanceof MassKernels.OscKernel) {
                    ((MassKernels.OscKernel) m).findSharedCoefficients();
                }
            }
        }
    }

    /**
     * Clears the x and y forces of the one-dimensional masses if something outside the kernels may have written
     * them since the last step ({@link #offAxisResidue}): they never move such a mass, and its kernels only clear
     * them when an interaction can write them ({@link #offAxisWriters}). Call before a step; allocates nothing.
     */
    void settleOffAxisForces() {
        if (!offAxisResidue) {
            return;
        }
        offAxisResidue = false;
        clearXY(start(MassKind.MASS1D), end(MassKind.MASS1D));
        clearXY(start(MassKind.OSC1D), end(MassKind.OSC1D));
    }

    private void clearXY(int s, int e) {
        java.util.Arrays.fill(fx, s, e, 0.0);
        java.util.Arrays.fill(fy, s, e, 0.0);
    }

    /** @return true if slot s holds a one-dimensional mass (Mass1D or Osc1D). */
    boolean isOneDimensional(int s) {
        return s >= start(MassKind.MASS1D) && s < end(MassKind.MASS1D)
                || s >= start(MassKind.OSC1D) && s < end(MassKind.OSC1D);
    }

    /** @return true if some link of a kind with x or y forces, or some contact group, touches a 1-D mass. */
    private boolean findOffAxisWriters() {
        if (start(MassKind.MASS1D) == end(MassKind.MASS1D) && start(MassKind.OSC1D) == end(MassKind.OSC1D)) {
            return false;
        }
        for (LinkBatch b : batches) {
            if (b == null || b.kind.isOneDimensional()) {
                continue;
            }
            for (int j = 0; j < b.n; j++) {
                if (isOneDimensional(b.a[j]) || isOneDimensional(b.b[j])) {
                    return true;
                }
            }
        }
        for (ContactGroupKernel g : groups) {
            for (int s : g.members()) {
                if (isOneDimensional(s)) {
                    return true;
                }
            }
        }
        return false;
    }

    int kernelsVersion() {
        return kernelsVersion;
    }

    /** @return the number of elements the plan updates per step: masses plus links (all kinds). */
    public int elementCount() {
        int n = nMass;
        for (LinkBatch b : batches) {
            if (b != null) {
                n += b.n;
            }
        }
        return n;
    }

    /** @return the names of the kernels this plan runs per step, in order, for diagnostics. */
    public String[] kernelNames() {
        java.util.ArrayList<String> names = new java.util.ArrayList<>();
        for (Kernel k : kernels) {
            if (k instanceof StencilKernel && ((StencilKernel) k).masses() != null) {
                // a run that also moves its masses: both computations, the masses first
                names.add(((StencilKernel) k).masses().getClass().getSimpleName());
            }
            names.add(k.getClass().getSimpleName());
        }
        return names.toArray(new String[0]);
    }

    int start(MassKind k) {
        return kindStart[k.ordinal()];
    }

    int end(MassKind k) {
        return kindStart[k.ordinal() + 1];
    }

    LinkBatch batch(LinkKind k) {
        return batches[k.ordinal()];
    }

    /**
     * Selects the kernels for the kinds present and the effects switched on: the mass kernels (in kind order),
     * then the stencil runs that move their own masses (see below), then the interaction kernels (in link-kind
     * order; within a batch the index-array links, then the runs).
     *
     * <p>A stencil run with offset 1 (a chain, or the rows of a mesh) whose slots all belong to one mass kind,
     * and overlap no other such run, takes over the mass update of those slots ({@link StencilKernel#fused}):
     * one sweep over the chain's memory per step instead of two. The kind's own kernel then covers the rest of
     * its slots, if any. Only the order in which forces from different kernels are summed changes.
     */
    void selectKernels() {
        java.util.ArrayList<Kernel> list = new java.util.ArrayList<>();
        boolean plainMasses = !medium.hasGravity() && !medium.hasFriction();
        boolean writers = findOffAxisWriters();
        if (writers != offAxisWriters) {
            offAxisWriters = writers;
            offAxisResidue = true;   // forces an interaction wrote under the old selection must not linger
        }
        boolean anyRun = false;
        for (LinkBatch b : batches) {
            anyRun |= b != null && b.runs.length > 0;
        }
        if (anyRun && stencilVecX == null) {
            stencilVecX = new double[nMass];
            stencilVecY = new double[nMass];
            stencilVecZ = new double[nMass];
            stencilDist = new double[nMass];
            stencilFarX = new double[nMass];
            stencilFarY = new double[nMass];
            stencilFarZ = new double[nMass];
        }
        // runs that move their own masses, and the slot ranges they take
        java.util.IdentityHashMap<StencilRun, StencilKernel> fused = new java.util.IdentityHashMap<>();
        java.util.ArrayList<int[]> taken = new java.util.ArrayList<>();
        for (LinkKind k : LinkKind.values()) {
            LinkBatch b = batch(k);
            if (b == null) {
                continue;
            }
            for (StencilRun run : b.runs) {
                MassKind kind = sweepRuns && run.o == 1 ? kindHolding(run.s, run.e + 1) : null;
                if (kind == null || overlaps(taken, run.s, run.e + 1)) {
                    continue;
                }
                MassKernels.SlotKernel masses =
                        (MassKernels.SlotKernel) MassKernels.create(kind, this, run.s, run.e + 1, plainMasses);
                fused.put(run, StencilKernel.fused(run, this, masses));
                taken.add(new int[] {run.s, run.e + 1});
            }
        }
        taken.sort((u, v) -> Integer.compare(u[0], v[0]));
        for (MassKind k : MassKind.values()) {
            int s = start(k);
            int e = end(k);
            // the kind's slots that no fused run moves
            for (int[] t : taken) {
                if (t[0] >= s && t[1] <= e) {
                    if (t[0] > s) {
                        list.add(MassKernels.create(k, this, s, t[0], plainMasses));
                    }
                    s = t[1];
                }
            }
            if (s < e) {
                list.add(MassKernels.create(k, this, s, e, plainMasses));
            }
        }
        for (LinkKind k : LinkKind.values()) {
            LinkBatch b = batch(k);
            if (b == null) {
                continue;
            }
            for (StencilRun run : b.runs) {
                if (fused.containsKey(run)) {
                    list.add(fused.get(run));
                }
            }
        }
        for (LinkKind k : LinkKind.values()) {
            LinkBatch b = batch(k);
            if (k == LinkKind.BUBBLE3D) {
                // contact groups take the place of explicit contacts: right after the Contact3D batch
                java.util.Collections.addAll(list, groups);
            }
            if (b == null || b.n == 0) {
                continue;
            }
            if (b.nIrregular > 0) {
                list.add(LinkKernels.create(b, this));
            }
            for (StencilRun run : b.runs) {
                if (!fused.containsKey(run)) {
                    list.add(sweepRuns ? StencilKernel.sweep(run, this) : StencilKernel.twoPass(run, this));
                }
            }
        }
        kernels = list.toArray(new Kernel[0]);
        kernelsVersion++;
        seenMassParams = -1;   // new oscillator kernels look at their masses' coefficients before their first step
    }

    /** @return the mass kind whose slots include all of [s, e), or null if they span several kinds. */
    private MassKind kindHolding(int s, int e) {
        for (MassKind k : MassKind.values()) {
            if (start(k) <= s && e <= end(k)) {
                return k;
            }
        }
        return null;
    }

    private static boolean overlaps(java.util.List<int[]> ranges, int s, int e) {
        for (int[] t : ranges) {
            if (s < t[1] && t[0] < e) {
                return true;
            }
        }
        return false;
    }
}
