package tactus;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import tactus.internal.model.Check;

/**
 * Builds strings, meshes, beams and volumes of masses on a regular grid, linked by
 * spring-dampers to their neighbours, with the names, links and subsets of the paper's engine
 * (miPhysics v1.1), so that sketches can address the generated masses by name.
 *
 * <p>A generator fills a block of {@code dimX * dimY * dimZ} masses. The mass at grid point
 * (i, j, k) is named {@code matPrefix_i_j_k} and starts at {@code (i, j, k) * dist}, rotated by
 * {@link #setRotation} about the grid origin then moved by {@link #setTranslation}. Each mass is
 * linked to every other mass within {@code span} grid steps along each axis (a Chebyshev
 * neighbourhood: span 1 links the faces, edges and corners of each grid cell), once per pair,
 * by a {@link SpringDamper3D} of rest length {@code |(di, dj, dk)| * l0}.
 *
 * <pre>
 * TopoGenerator q = new TopoGenerator(mdl, "mass", "spring");
 * q.setDim(30, 2, 5, 1);
 * q.setParams(1, 0.01, 0.003);
 * q.setGeometry(2, 2);
 * q.addBoundaryCondition(Bound.X_LEFT);
 * q.generate();
 * </pre>
 *
 * <p>Every setter validates its arguments and throws an {@link IllegalArgumentException} that
 * names the call and the value. {@link #generate()} checks everything before it adds anything:
 * a rejected generation leaves the model unchanged.
 */
public class TopoGenerator {
    private final PhysicalModel model;
    private final String matPrefix;
    private int dimX = 1;
    private int dimY = 1;
    private int dimZ = 1;
    private int span;
    private boolean plane2D;
    private double mass;
    private double stiffness;
    private double damping;
    private double dist;
    private double l0;
    private float rotX, rotY, rotZ;
    private float tX, tY, tZ;
    private String matSubset = "";
    private String linkSubset = "";
    private final EnumSet<Bound> bounds = EnumSet.noneOf(Bound.class);
    /** Names of the masses made by the last {@link #generate()}, in creation order. */
    private final List<String> generated = new ArrayList<>();

    /**
     * Creates a generator that adds to {@code model}.
     *
     * @param model the model to build into
     * @param matPrefix the prefix of the mass names ({@code matPrefix_i_j_k}); it also prefixes the
     *     link names, as in the paper's engine (see {@link #generate()})
     * @param linkPrefix kept for compatibility; the paper's engine does not use it in link names
     */
    public TopoGenerator(PhysicalModel model, String matPrefix, String linkPrefix) {
        if (model == null) {
            throw new IllegalArgumentException("TopoGenerator: the model must not be null");
        }
        if (matPrefix == null || matPrefix.isEmpty()) {
            throw new IllegalArgumentException("TopoGenerator: the mass prefix must be a non-empty string, got "
                    + (matPrefix == null ? "null" : "\"\""));
        }
        this.model = model;
        this.matPrefix = matPrefix;
    }

    /**
     * Sets the size of the block and the reach of the links.
     *
     * @param dx number of masses along x, &ge; 1
     * @param dy number of masses along y, &ge; 1
     * @param dz number of masses along z, &ge; 1
     * @param span how many grid steps a link reaches along each axis, &ge; 0 (0: no links; 1: the
     *     nearest neighbours and the diagonals of each cell; 2 and more: longer links too)
     */
    public void setDim(int dx, int dy, int dz, int span) {
        if (dx < 1 || dy < 1 || dz < 1) {
            throw new IllegalArgumentException("TopoGenerator.setDim(\"" + matPrefix + "\"): every dimension must be >= 1, got "
                    + dx + " x " + dy + " x " + dz);
        }
        if (span < 0) {
            throw new IllegalArgumentException("TopoGenerator.setDim(\"" + matPrefix + "\"): span must be >= 0, got " + span);
        }
        dimX = dx;
        dimY = dy;
        dimZ = dz;
        this.span = span;
    }

    /** Chooses {@link Mass2DPlane} masses (moving in their initial z plane) instead of {@link Mass3D}. */
    public void set2DPlane(boolean val) {
        plane2D = val;
    }

    /**
     * Sets the module parameters, in the model's unit system.
     *
     * @param mParam inertia of every mass (REAL_UNITS: kg), finite and &gt; 0
     * @param kParam stiffness of every link (REAL_UNITS: N/m), finite
     * @param zParam damping of every link (REAL_UNITS: N·s/m), finite
     */
    public void setParams(double mParam, double kParam, double zParam) {
        Check.positive("TopoGenerator.setParams", matPrefix, "mass", mParam);
        Check.finite("TopoGenerator.setParams", matPrefix, "K", kParam);
        Check.finite("TopoGenerator.setParams", matPrefix, "Z", zParam);
        mass = mParam;
        stiffness = kParam;
        damping = zParam;
    }

    /**
     * Sets the spacing of the grid and the rest length of its links.
     *
     * @param d distance between neighbouring masses along an axis (model length units), &ge; 0
     * @param l rest length of an axis-aligned link of one grid step, &ge; 0; a link spanning
     *     (di, dj, dk) grid steps rests at {@code l * sqrt(di^2 + dj^2 + dk^2)}
     */
    public void setGeometry(double d, double l) {
        Check.nonNegative("TopoGenerator.setGeometry", matPrefix, "distance", d);
        Check.nonNegative("TopoGenerator.setGeometry", matPrefix, "rest length", l);
        dist = d;
        l0 = l;
    }

    /** Sets the rotation of the block about its grid origin, in radians: about x, then y, then z. */
    public void setRotation(float x, float y, float z) {
        requireFinite("setRotation", x, y, z);
        rotX = x;
        rotY = y;
        rotZ = z;
    }

    /** Sets the translation of the block, applied after the rotation (model length units). */
    public void setTranslation(float x, float y, float z) {
        requireFinite("setTranslation", x, y, z);
        tX = x;
        tY = y;
        tZ = z;
    }

    /** Puts every generated mass in this mass subset (created if needed); "" for none. */
    public void setMatSubsetName(String name) {
        matSubset = name == null ? "" : name;
    }

    /** Puts every generated link in this link subset (created if needed); "" for none. */
    public void setLinkSubsetName(String name) {
        linkSubset = name == null ? "" : name;
    }

    /** Adds a boundary condition applied at the end of {@link #generate()}. */
    public void addBoundaryCondition(Bound b) {
        if (b == null) {
            throw new IllegalArgumentException("TopoGenerator.addBoundaryCondition(\"" + matPrefix + "\"): the bound must not be null");
        }
        bounds.add(b);
    }

    /**
     * Adds the block to the model: the masses in (i, j, k) order, then the links of each mass in
     * the same order, then the boundary conditions (masses turned into {@link Ground3D} fixed
     * points, keeping their links).
     *
     * <p>Link names follow the paper's engine: every link that starts at mass (i, j, k) is named
     * {@code matPrefix + "1_" + i + j + k}, so names repeat; calls that address a repeated name reach the
     * first link, as in the paper's engine.
     *
     * @throws IllegalArgumentException if the parameters were never set, a generated mass name is
     *     already taken, or the two subset names are equal; the model is then unchanged
     */
    public void generate() {
        String op = "TopoGenerator.generate";
        if (!(mass > 0)) {
            throw Check.fail(op, matPrefix, "call setParams(M, K, Z) with M > 0 before generate()");
        }
        if (!matSubset.isEmpty() && matSubset.equals(linkSubset)) {
            throw Check.fail(op, matPrefix, "the mass subset and the link subset need different names, both are \""
                    + matSubset + "\"");
        }
        locked(() -> {
            for (int i = 0; i < dimX; i++) {
                for (int j = 0; j < dimY; j++) {
                    for (int k = 0; k < dimZ; k++) {
                        String n = TopoGrid.massName(matPrefix, i, j, k);
                        if (model.matExists(n)) {
                            throw Check.fail(op, n, "a mass with this name already exists; use another prefix");
                        }
                    }
                }
            }
            int linksBefore = model.getNumberOfLinks();
            List<String> made = new ArrayList<>();
            try {
                ensureSubset(matSubset, true);
                ensureSubset(linkSubset, false);
                addMasses(made);
                addLinks();
                for (String n : TopoGrid.fixedMasses(matPrefix, dimX, dimY, dimZ, bounds)) {
                    model.changeToFixedPoint(n);
                }
            } catch (RuntimeException e) {
                while (model.getNumberOfLinks() > linksBefore) {
                    model.removeLink(model.getNumberOfLinks() - 1);
                }
                for (String n : made) {
                    model.removeMatAndConnectedLinks(n);
                }
                throw e;
            }
            generated.clear();
            generated.addAll(made);
        });
    }

    /**
     * Removes the masses of this generator's block (and their links) that lie outside
     * ({@code ext = true}) or inside ({@code ext = false}) a sphere centred on the block's centre,
     * to carve balls and shells out of a generated volume.
     *
     * @param radius sphere radius (model length units), finite
     * @param ext true to keep the inside of the sphere, false to keep the outside
     */
    public void conditionAlongSphere(double radius, boolean ext) {
        Check.finite("TopoGenerator.conditionAlongSphere", matPrefix, "radius", radius);
        Vect3D centre = TopoGrid.transform(rotationMatrix(), (dimX - 1) * dist / 2.0, (dimY - 1) * dist / 2.0,
                (dimZ - 1) * dist / 2.0, tX, tY, tZ);
        locked(() -> {
            List<String> keep = new ArrayList<>();
            Vect3D p = new Vect3D();
            for (String n : generated) {
                if (!model.matExists(n)) {
                    continue;
                }
                double d = model.getMatPosition(n, p).dist(centre);
                if (ext ? d > radius : d < radius) {
                    model.removeMatAndConnectedLinks(n);
                } else {
                    keep.add(n);
                }
            }
            generated.clear();
            generated.addAll(keep);
        });
    }

    /** Runs a sequence of model calls holding the model's lock, whatever form getLock() returns. */
    private void locked(Runnable body) {
        Object lock = model.getLock();
        if (lock instanceof java.util.concurrent.locks.Lock) {
            java.util.concurrent.locks.Lock l = (java.util.concurrent.locks.Lock) lock;
            l.lock();
            try {
                body.run();
            } finally {
                l.unlock();
            }
        } else {
            synchronized (lock) {
                body.run();
            }
        }
    }

    private void ensureSubset(String name, boolean mats) {
        if (name.isEmpty() || model.subsetExists(name)) {
            // An existing subset: the generated modules join it (adding to a subset of the other kind fails below
            // with the model's own message, and is rolled back).
            return;
        }
        if (mats) {
            model.createMatSubset(name);
        } else {
            model.createLinkSubset(name);
        }
    }

    private void addMasses(List<String> made) {
        double[] r = rotationMatrix();
        Vect3D still = new Vect3D();
        for (int i = 0; i < dimX; i++) {
            for (int j = 0; j < dimY; j++) {
                for (int k = 0; k < dimZ; k++) {
                    String n = TopoGrid.massName(matPrefix, i, j, k);
                    Vect3D pos = TopoGrid.transform(r, i * dist, j * dist, k * dist, tX, tY, tZ);
                    if (plane2D) {
                        model.addMass2DPlane(n, mass, pos, still);
                    } else {
                        model.addMass3D(n, mass, pos, still);
                    }
                    made.add(n);
                    if (!matSubset.isEmpty()) {
                        model.addMatToSubset(n, matSubset);
                    }
                }
            }
        }
    }

    private void addLinks() {
        int[][] offsets = TopoGrid.halfOffsets(span);
        for (int i = 0; i < dimX; i++) {
            for (int j = 0; j < dimY; j++) {
                for (int k = 0; k < dimZ; k++) {
                    String from = TopoGrid.massName(matPrefix, i, j, k);
                    String name = TopoGrid.linkName(matPrefix, i, j, k);
                    for (int[] o : offsets) {
                        int a = i + o[0], b = j + o[1], c = k + o[2];
                        if (a < 0 || b < 0 || c < 0 || a >= dimX || b >= dimY || c >= dimZ) {
                            continue;
                        }
                        double rest = Math.sqrt(o[0] * o[0] + o[1] * o[1] + o[2] * o[2]) * l0;
                        addLink(name, rest, from, TopoGrid.massName(matPrefix, a, b, c));
                    }
                }
            }
        }
    }

    /** Adds one link under the paper's name (names repeat, as in the paper's engine). */
    private void addLink(String name, double rest, String m1, String m2) {
        model.addSpringDamper3D(name, rest, stiffness, damping, m1, m2);
        if (!linkSubset.isEmpty()) {
            model.addLinkToSubset(model.getNumberOfLinks() - 1, linkSubset);
        }
    }

    private double[] rotationMatrix() {
        return TopoGrid.rotation(rotX, rotY, rotZ);
    }

    private void requireFinite(String op, float x, float y, float z) {
        if (!Float.isFinite(x) || !Float.isFinite(y) || !Float.isFinite(z)) {
            throw new IllegalArgumentException("TopoGenerator." + op + "(\"" + matPrefix + "\"): every component must be finite, got ("
                    + x + ", " + y + ", " + z + ")");
        }
    }
}
