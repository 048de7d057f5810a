package tactus.audio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ddf.minim.ugens.Gain;
import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;

/** PhyUGen's output path: pan law, mono mix, DC blocker, rate tracking, patching, listening kinds, validation. */
class PhyUGenTest {
    static final int RATE = 44100;

    static final class PluckedString extends PhyUGen {
        PluckedString(double pan) {
            super(RATE);
            StringModel.build(mdl, 7, 0.001);
            mdl.init();
            listenToMass(StringModel.mass(3), SteppedModel.Y, 300, pan);
        }
    }

    /** A subclass that, like the paper's sketches, assigns its own mdl in the constructor. */
    static final class OwnModel extends PhyUGen {
        OwnModel() {
            super(RATE);
            mdl = new PhysicalModel(RATE, 60);
            StringModel.build(mdl, 7, 0.001);
            mdl.init();
            listenToMass(StringModel.mass(3), SteppedModel.Y, 300, 0);
        }
    }

    @Test
    void equalPowerPan() {
        double pan = 0.5;
        float[][] s = OfflineRenderer.renderToArray(new PluckedString(pan), RATE, 2, 0.1);
        double a = (pan + 1) * Math.PI / 4;
        double energy = 0;
        for (int i = 0; i < s[0].length; i++) {
            assertEquals(s[0][i] * Math.sin(a), s[1][i] * Math.cos(a), 1e-6, "frame " + i);
            energy += s[0][i] * s[0][i] + s[1][i] * s[1][i];
        }
        assertTrue(energy > 1, "it sounds");
        // mono: the same point summed with its gain alone (pan ignored), so centred stereo is mono / sqrt 2
        float[][] mono = OfflineRenderer.renderToArray(new PluckedString(0.5), RATE, 1, 0.1);
        float[][] centred = OfflineRenderer.renderToArray(new PluckedString(0), RATE, 2, 0.1);
        for (int i = 0; i < mono[0].length; i++) {
            assertEquals(mono[0][i] * Math.sqrt(0.5), centred[0][i], 1e-6, "frame " + i);
            assertEquals(centred[0][i], centred[1][i], 0f);
        }
        PluckedString forced = new PluckedString(0.5);
        forced.setMono(true);
        float[][] forcedMono = OfflineRenderer.renderToArray(forced, RATE, 2, 0.1);
        for (int i = 0; i < mono[0].length; i++) {
            assertEquals(mono[0][i], forcedMono[0][i], 0f);
            assertEquals(mono[0][i], forcedMono[1][i], 0f);
        }
    }

    /** A free mass drifting at constant speed: its displacement is a ramp of slope v per sample. */
    private static PhyUGen drifting(double velocityPerSecond) {
        PhysicalModel pm = new PhysicalModel(RATE);
        pm.addMass3D("m", 1, new Vect3D(0, 0, 0), new Vect3D(velocityPerSecond, 0, 0));
        pm.init();
        PhyUGen u = new PhyUGen(pm);
        u.listenToMass("m", SteppedModel.X, 1, 0);
        return u;
    }

    @Test
    void dcBlockerTurnsARampIntoItsClosedFormConstant() {
        PhyUGen raw = drifting(441);
        raw.setDcBlockerEnabled(false);
        float[][] ramp = OfflineRenderer.renderToArray(raw, RATE, 1, 0.05);
        double slope = ramp[0][1000] - ramp[0][999];
        assertEquals(441.0 / RATE, slope, 1e-6, "the model drifts at v / rate per sample");

        PhyUGen paper = drifting(441);
        assertEquals(PhyUGen.DEFAULT_DC_COEFFICIENT, paper.dcBlockerCoefficient(), 0);
        float[][] y = OfflineRenderer.renderToArray(paper, RATE, 1, 0.05);
        // y(n) = slope + r y(n-1) tends to slope / (1 - r)
        assertEquals(slope / (1 - 0.95), y[0][y[0].length - 1], 1e-5);

        PhyUGen gentle = drifting(441);
        gentle.setDcBlocker(0.995);
        float[][] g = OfflineRenderer.renderToArray(gentle, RATE, 1, 0.2);
        assertEquals(slope / (1 - 0.995), g[0][g[0].length - 1], 1e-4);
        assertEquals(342.5, DcBlocker.cornerHz(0.95, RATE), 0.1);
    }

    @Test
    void modelRateFollowsTheOutputRateTimesK() {
        PhysicalModel pm = new PhysicalModel(RATE);
        StringModel.build(pm, 7, 0.001);
        pm.init();
        PhyUGen u = new PhyUGen(pm);
        u.listenToMass(StringModel.mass(3), SteppedModel.Y, 300, 0);
        OfflineRenderer.renderToArray(u, 48000, 1, 0.01);
        assertEquals(48000, pm.getSimRate());
        u.setOversampling(2);
        assertEquals(96000, pm.getSimRate());
        OfflineRenderer.renderToArray(u, 22050, 1, 0.01);
        assertEquals(44100, pm.getSimRate());
        u.setOversampling(1);
        assertEquals(22050, pm.getSimRate());
    }

    @Test
    void patchesIntoAGainLikeAnyUGen() {
        float[][] alone = OfflineRenderer.renderToArray(new PluckedString(0), RATE, 1, 0.05);
        Gain gain = new Gain(-6f);
        new PluckedString(0).patch(gain);
        float[][] through = OfflineRenderer.renderToArray(gain, RATE, 1, 0.05);
        double factor = Math.pow(10, -6 / 20.0);
        for (int i = 0; i < alone[0].length; i++) {
            assertEquals(alone[0][i] * factor, through[0][i], 1e-6, "frame " + i);
        }
    }

    @Test
    void aSubclassMayAssignItsOwnModel() {
        float[][] own = OfflineRenderer.renderToArray(new OwnModel(), RATE, 1, 0.05);
        float[][] given = OfflineRenderer.renderToArray(new PluckedString(0), RATE, 1, 0.05);
        for (int i = 0; i < own[0].length; i++) {
            assertEquals(given[0][i], own[0][i], 0f, "frame " + i);
        }
    }

    @Test
    void elongationAndTensionPointsFollowTheSpringLaw() {
        PhysicalModel pm = new PhysicalModel(RATE);
        StringModel.build(pm, 7, 0.01);
        pm.init();
        PhyUGen e = new PhyUGen(pm);
        e.setDcBlockerEnabled(false);
        e.listenToElongation("s3", 1, 0);
        double seconds = 14.0 * PhyUGen.DEFAULT_BLOCK_SIZE / RATE;   // whole blocks: the last sample is the last step
        float[][] elong = OfflineRenderer.renderToArray(e, RATE, 1, seconds);
        PhysicalModel pm2 = new PhysicalModel(RATE);
        StringModel.build(pm2, 7, 0.01);
        pm2.init();
        PhyUGen t = new PhyUGen(pm2);
        t.setDcBlockerEnabled(false);
        t.listenToTension("s3", 1, 0);
        float[][] tension = OfflineRenderer.renderToArray(t, RATE, 1, seconds);
        double rest = StringModel.D - StringModel.L0;
        for (int i = 0; i < elong[0].length; i += 37) {
            assertTrue(Math.abs(elong[0][i] - rest) < 1e-3, "elongation near D - L0");
            // undamped spring: tension = K * elongation
            assertEquals(StringModel.K * elong[0][i], tension[0][i], 1e-6, "frame " + i);
        }
        assertEquals(pm.getLinkElongation("s3"), elong[0][elong[0].length - 1], 1e-7);
    }

    @Test
    void validationNamesTheElementAndTheValue() {
        PhysicalModel pm = new PhysicalModel(RATE);
        StringModel.build(pm, 7, 0.001);
        pm.addAttractor3D("pull", 0.01, 0.001, "m1", "m2");
        pm.init();
        PhyUGen u = new PhyUGen(pm);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> u.listenToMass("nope", SteppedModel.Y, 1, 0));
        assertTrue(e.getMessage().contains("nope"), e.getMessage());
        assertTrue(assertThrows(IllegalArgumentException.class, () -> u.listenToMass("m1", 3, 1, 0)).getMessage()
                .contains("3"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> u.listenToMass("m1", 1, 1, 2)).getMessage()
                .contains("2.0"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> u.listenToTension("pull", 1, 0)).getMessage()
                .contains("Attractor3D"));
        assertThrows(IllegalArgumentException.class, () -> u.setDcBlocker(1));
        assertThrows(IllegalArgumentException.class, () -> u.setOversampling(0));
        assertThrows(IllegalArgumentException.class, () -> u.attachAvatar("m1", new AvatarExchange()));
        assertEquals(0, u.listeningPoints().length, "rejected calls add nothing");
    }
}
