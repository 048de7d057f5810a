package tactus.haptics;

import static java.util.concurrent.TimeUnit.MILLISECONDS;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import processing.core.PApplet;
import processing.core.PVector;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.emulator.Hand;
import tactus.haptics.emulator.PtyPair;
import tactus.haptics.pantograph.PantographKinematics;
import tactus.haptics.transport.SerialTransport;

/**
 * A sketch written the hAPI 2.x way (its own Mechanisms subclass, PVector arrays, a ScheduledExecutorService
 * at 1 kHz, data_available() before each read) runs against the emulator over a pty, through
 * {@code new Board(this, port, 0)}.
 */
class HapiSketchPortTest {

    /** A sketch's own pantograph, as sketches ship one next to their .pde (written here, not copied). */
    public static class SketchPantograph extends Mechanisms {
        private float l = 0.05f;
        private float bigL = 0.07f;
        private float d = 0.02f;
        private float th1;
        private float th2;
        private float x;
        private float y;
        private float t1;
        private float t2;
        private float jxx;
        private float jxy;
        private float jyx;
        private float jyy;

        @Override
        public void forwardKinematics(float[] angles) {
            th1 = (float) Math.toRadians(angles[0]);
            th2 = (float) Math.toRadians(angles[1]);
            float ax = l * (float) Math.cos(th1);
            float ay = l * (float) Math.sin(th1);
            float bx = d + l * (float) Math.cos(th2);
            float by = l * (float) Math.sin(th2);
            float hx = bx - ax;
            float hy = by - ay;
            float h = (float) Math.sqrt(hx * hx + hy * hy);
            float k = (float) Math.sqrt(bigL * bigL - h * h / 4) / h;
            x = (ax + bx) / 2 - k * hy;
            y = (ay + by) / 2 + k * hx;
            // Jacobian by central differences, good enough for a sketch
            float e = 1e-3f;
            jxx = (fx(th1 + e, th2) - fx(th1 - e, th2)) / (2 * e);
            jxy = (fx(th1, th2 + e) - fx(th1, th2 - e)) / (2 * e);
            jyx = (fy(th1 + e, th2) - fy(th1 - e, th2)) / (2 * e);
            jyy = (fy(th1, th2 + e) - fy(th1, th2 - e)) / (2 * e);
        }

        private float fx(float a, float b) {
            PantographKinematics k = new PantographKinematics(l, bigL, d);
            k.forward(a, b);
            return (float) k.x();
        }

        private float fy(float a, float b) {
            PantographKinematics k = new PantographKinematics(l, bigL, d);
            k.forward(a, b);
            return (float) k.y();
        }

        @Override
        public void torqueCalculation(float[] force) {
            t1 = jxx * force[0] + jyx * force[1];
            t2 = jxy * force[0] + jyy * force[1];
        }

        @Override
        public void forceCalculation() {
        }

        @Override
        public void positionControl() {
        }

        @Override
        public void inverseKinematics() {
        }

        @Override
        public void set_mechanism_parameters(float[] p) {
            l = p[0];
            bigL = p[1];
            d = p[2];
        }

        @Override
        public void set_sensor_data(float[] data) {
        }

        @Override
        public float[] get_coordinate() {
            return new float[] {x, y};
        }

        @Override
        public float[] get_torque() {
            return new float[] {t1, t2};
        }

        @Override
        public float[] get_angle() {
            return new float[] {th1, th2};
        }
    }

    /** A headless PApplet that runs its registered dispose methods, as PApplet.dispose() does when a sketch stops. */
    static final class HeadlessApplet extends PApplet {
        void stopSketch() {
            handleMethods("dispose");
        }
    }

    @Test
    void helloWallStyleSketchRunsOnTheEmulatorOverAPty() throws Exception {
        Assumptions.assumeTrue(PtyPair.socatAvailable(), "socat is not installed");
        try (PtyPair pty = PtyPair.open()) {
            BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
            emulator.setHand(Hand.scripted((t, out) -> {
                out[0] = 0.005 * Math.sin(2 * Math.PI * t);   // at most 3 cm/s: 1.5 mm is 50 ms of lag
                out[1] = 0.08;
            }));
            emulator.serve(SerialTransport.open(pty.boardEnd(), 0));

            // --- the sketch, as written for hAPI (only the import changed) ---
            HeadlessApplet app = new HeadlessApplet();
            byte widgetOneID = 5;
            int CW = 0;
            Board haplyBoard = new Board(app, pty.hostEnd(), 0);
            Device widgetOne = new Device(widgetOneID, haplyBoard);
            Mechanisms pantograph = new SketchPantograph();
            widgetOne.set_mechanism(pantograph);
            widgetOne.add_actuator(1, CW, 1);
            widgetOne.add_actuator(2, CW, 2);
            widgetOne.add_encoder(1, CW, 180, 13824, 1);
            widgetOne.add_encoder(2, CW, 0, 13824, 2);
            widgetOne.device_set_parameters();
            PVector angles = new PVector(0, 0);
            PVector torques = new PVector(0, 0);
            PVector posEE = new PVector(0, 0);
            PVector fEE = new PVector(0, 0);
            AtomicInteger reads = new AtomicInteger();
            AtomicReference<Throwable> error = new AtomicReference<>();
            ScheduledExecutorService scheduler = Executors.newScheduledThreadPool(1);
            scheduler.scheduleAtFixedRate(() -> {
                try {
                    if (haplyBoard.data_available()) {
                        widgetOne.device_read_data();
                        angles.set(widgetOne.get_device_angles());
                        posEE.set(widgetOne.get_device_position(angles.array()));
                        reads.incrementAndGet();
                    }
                    fEE.set(0.5f, -0.3f);
                    torques.set(widgetOne.set_device_torques(fEE.array()));
                    widgetOne.device_write_torques();
                } catch (Throwable t) {
                    error.compareAndSet(null, t);
                    throw t;
                }
            }, 1, 1, MILLISECONDS);
            Thread.sleep(600);
            // the torques the sketch computes are the ones the motors apply (firmware quantisation), compared while
            // the sketch still writes: once it stops, the board's 50 ms torque watchdog zeroes them (beside a CPU hog
            // the test thread can be late by that much); a late writer can let it trip now and then, so the check
            // waits (at most 1 s) for a moment when the two agree
            double step = 0.123 / 1023;
            boolean agree = false;
            double sketchX = 0;
            double motorX = 0;
            long agreeBy = System.nanoTime() + 1_000_000_000L;
            while (!agree && System.nanoTime() < agreeBy) {
                sketchX = torques.x;
                motorX = emulator.motorTorque(1);
                double sketchY = torques.y;
                double motorY = emulator.motorTorque(2);
                agree = Math.abs(sketchX - motorX) <= 2 * step + 0.02 * Math.abs(sketchX)
                        && Math.abs(sketchY - motorY) <= 2 * step + 0.02 * Math.abs(sketchY) && sketchX != 0;
                Thread.sleep(1);
            }
            assertTrue(agree, "the motors apply the sketch's torques: sketch " + sketchX + ", motor " + motorX + " N m");
            scheduler.shutdown();
            scheduler.awaitTermination(1, java.util.concurrent.TimeUnit.SECONDS);
            // --- end of the sketch ---

            assertEquals(null, error.get());
            assertTrue(reads.get() > 50, "reads: " + reads.get());
            // the position the sketch sees is the emulated handle's (within a few ms of motion and one count)
            assertEquals(emulator.x(), posEE.x, 1.5e-3);
            assertEquals(emulator.y(), posEE.y, 1.5e-3);
            assertEquals(0f, posEE.z);
            assertEquals(0, haplyBoard.idMismatches());
            app.stopSketch();   // Processing's stop: the board sends zero torques and closes
            long deadline = System.nanoTime() + 2_000_000_000L;
            while (emulator.duty(1) != 0 && System.nanoTime() < deadline) {
                Thread.sleep(1);
            }
            assertEquals(0, emulator.duty(1));
            assertEquals(0, emulator.duty(2));
            assertTrue(haplyBoard.isClosed());
            emulator.close();
        }
    }

    @Test
    void paperStyleHapticThreadDrivesAModelThroughTheEmulator() throws Exception {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        emulator.setHand(Hand.scripted((t, out) -> {
            out[0] = 0.015 * Math.sin(2 * Math.PI * t);
            out[1] = 0.08;
        }));
        // the paper's haptics-only sketch: its own thread, hAPI calls, setHapticPosition / getHapticForce
        PhysicalModel mdl = new PhysicalModel(1000);
        mdl.addHapticInput3D("hapticMass", new Vect3D(), 10);
        for (int i = 0; i < 10; i++) {
            mdl.addMass3D("m" + i, 50, new Vect3D(0.1 * (i + 1), 0, 0), new Vect3D());
        }
        for (int i = 0; i < 9; i++) {
            mdl.addSpringDamper3D("k" + i, 0.1, 0.003, 0.05, "m" + i, "m" + (i + 1));
        }
        mdl.addSpringDamper3D("grip", 0.1, 0.003, 0.05, "hapticMass", "m0");
        mdl.init();
        Board haplyBoard = new Board(emulator.connect());
        Device widgetOne = new Device((byte) 5, haplyBoard);
        widgetOne.set_mechanism(new Pantograph());
        widgetOne.add_actuator(1, 0, 1);
        widgetOne.add_actuator(2, 0, 2);
        widgetOne.add_encoder(1, 0, 180, 13824, 1);
        widgetOne.add_encoder(2, 0, 0, 13824, 2);
        widgetOne.device_set_parameters();
        float posGain = 200;
        float forceGain = 100;
        PVector angles = new PVector();
        PVector posEE = new PVector();
        PVector fEE = new PVector();
        AtomicInteger ticks = new AtomicInteger();
        AtomicReference<Throwable> error = new AtomicReference<>();
        double[] maxForce = {0};
        ScheduledExecutorService scheduler = Executors.newScheduledThreadPool(1);
        scheduler.scheduleAtFixedRate(() -> {
            try {
                if (haplyBoard.data_available()) {
                    widgetOne.device_read_data();
                    angles.set(widgetOne.get_device_angles());
                    posEE.set(widgetOne.get_device_position(angles.array()));
                }
                mdl.setHapticPosition("hapticMass", new Vect3D(-posGain * posEE.x, posGain * (posEE.y - 0.08f), 0));
                mdl.computeStep();
                Vect3D f = mdl.getHapticForce("hapticMass");
                fEE.set((float) (-forceGain * f.x), (float) (forceGain * f.y));
                maxForce[0] = Math.max(maxForce[0], fEE.mag());
                widgetOne.set_device_torques(fEE.array());
                widgetOne.device_write_torques();
                ticks.incrementAndGet();
            } catch (Throwable t) {
                error.compareAndSet(null, t);
                throw t;
            }
        }, 1, 1, MILLISECONDS);
        Thread.sleep(800);
        scheduler.shutdown();
        scheduler.awaitTermination(1, java.util.concurrent.TimeUnit.SECONDS);
        assertEquals(null, error.get());
        assertTrue(ticks.get() > 100, "ticks: " + ticks.get());
        assertTrue(maxForce[0] > 0 && Double.isFinite(maxForce[0]), "the moving handle drags the chain: " + maxForce[0]);
        assertTrue(emulator.writes() >= ticks.get());
        haplyBoard.close();
        assertEquals(0, emulator.duty(1));
        assertEquals(0, emulator.duty(2));
    }
}
