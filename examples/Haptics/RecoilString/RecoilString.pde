/*
 * RecoilString: a string tied to a fixed point (green) at one end and to a very heavy mass
 * (yellow) at the other. Thrown away from the fixed point, the heavy mass stretches the string
 * until it recoils, flies back while the string goes limp, and stretches it again. Pluck the
 * string or push it with the avatar (red) and you bend the heavy mass's course: the string
 * coils and wraps around your hand.
 *
 * With no Haply plugged in, the sketch runs the board emulator and the mouse is your hand.
 *
 * Controls: R throw the heavy mass again, H make it heavier or lighter, T print the loop's
 * telemetry. The string's links are ropes: they pull when stretched and go limp, never push.
 * Units: ALGO_UNITS, 1 model unit = 1 pixel, parameters per step of the 1 kHz haptic loop.
 */

import tactus.*;
import tactus.haptics.*;

PhysicalModel mdl;
HapticSession haptics;

int nMasses = 40;
float link = 9;            // rope length between neighbours, pixels (string: 41 links, 369 pixels)
float ropeK = 0.05;
float ropeZ = 0.01;
float endMass = 1000;      // the heavy end; each string mass weighs 1
float lightEnd = 200;
boolean heavyEnd = true;
float pluckRadius = 10;    // how close the avatar must come to touch the string, pixels
float anchorX = 150, anchorY = 300;
int[] index = new int[nMasses + 3];   // anchor, string masses, heavy end, avatar
int[] ropeIndex = new int[nMasses + 1];
double[] force = new double[2];

void setup() {
  size(800, 600);
  frameRate(60);
  // A Haply if one is plugged in, otherwise the emulator with the mouse as the hand.
  haptics = HapticSession.open(this);

  mdl = new PhysicalModel(1000, 60, paramSystem.ALGO_UNITS);
  mdl.setFriction(0.00005);
  mdl.addGround3D("anchor", new Vect3D(anchorX, anchorY, 0));
  for (int i = 0; i < nMasses; i++) {
    mdl.addMass2DPlane("s" + i, 1, new Vect3D(anchorX, anchorY, 0), new Vect3D());
  }
  mdl.addMass2DPlane("end", endMass, new Vect3D(anchorX, anchorY, 0), new Vect3D());
  mdl.addRope3D("r0", link, ropeK, ropeZ, "anchor", "s0");
  for (int i = 0; i + 1 < nMasses; i++) {
    mdl.addRope3D("r" + (i + 1), link, ropeK, ropeZ, "s" + i, "s" + (i + 1));
  }
  mdl.addRope3D("r" + nMasses, link, ropeK, ropeZ, "s" + (nMasses - 1), "end");

  mdl.addHapticInput3D("avatar", haptics.home(), 10);
  for (int i = 0; i < nMasses; i++) {
    mdl.addContact3D("pluck" + i, pluckRadius, 0.05, 0.005, "avatar", "s" + i);
  }
  mdl.addContact3D("shove", 24, 0.05, 0.01, "avatar", "end");
  mdl.init();
  throwEnd();

  index[0] = mdl.getMatIndex("anchor");
  for (int i = 0; i < nMasses; i++) {
    index[i + 1] = mdl.getMatIndex("s" + i);
  }
  index[nMasses + 1] = mdl.getMatIndex("end");
  index[nMasses + 2] = mdl.getMatIndex("avatar");
  for (int i = 0; i <= nMasses; i++) {
    ropeIndex[i] = mdl.getLinkIndex("r" + i);
  }

  HapticLoop loop = haptics.attach(mdl, "avatar");
  loop.setForceGain(0.6);   // newtons per model force unit: a 5-pixel press on the string is 0.15 N
  loop.start();             // 1 kHz; the haptic thread steps the model
}

/** Lays the string slack along a short line and throws the heavy end away from the anchor. */
void throwEnd() {
  for (int i = 0; i < nMasses; i++) {
    float u = (i + 1) / (float) (nMasses + 1);
    mdl.setMatPosition("s" + i, new Vect3D(anchorX + 80 * u, anchorY + 10 * sin(u * PI), 0));
    mdl.setMatVelocity("s" + i, new Vect3D());
  }
  mdl.setMatPosition("end", new Vect3D(anchorX + 80, anchorY, 0));
  mdl.setMatVelocity("end", new Vect3D(150, 40, 0));   // pixels per second
}

void draw() {
  background(16, 18, 26);
  ModelSnapshot s = mdl.getSnapshot();   // never waits for the haptic thread

  double[] ws = new double[4];
  haptics.workspace(ws);
  noFill();
  stroke(50, 56, 72);
  strokeWeight(1);
  rect((float) ws[0], (float) ws[2], (float) (ws[1] - ws[0]), (float) (ws[3] - ws[2]));

  // the string, brighter where it is stretched
  strokeWeight(2);
  for (int i = 0; i <= nMasses; i++) {
    float stretch = (float) s.getLinkElongation(ropeIndex[i]);
    stroke(lerpColor(color(120, 140, 170), color(255, 240, 200), constrain(stretch / 3, 0, 1)));
    line((float) s.x(index[i]), (float) s.y(index[i]), (float) s.x(index[i + 1]), (float) s.y(index[i + 1]));
  }
  noStroke();
  fill(80, 220, 110);
  ellipse((float) s.x(index[0]), (float) s.y(index[0]), 16, 16);
  fill(250, 210, 60);
  float endSize = heavyEnd ? 28 : 18;
  ellipse((float) s.x(index[nMasses + 1]), (float) s.y(index[nMasses + 1]), endSize, endSize);

  float ax = (float) s.x(index[nMasses + 2]);
  float ay = (float) s.y(index[nMasses + 2]);
  haptics.forceInModel(force);
  stroke(255, 150, 60);
  strokeWeight(3);
  line(ax, ay, ax + 40 * (float) force[0], ay + 40 * (float) force[1]);
  noStroke();
  fill(230, 60, 50);
  ellipse(ax, ay, 2 * pluckRadius, 2 * pluckRadius);

  fill(230);
  textSize(14);
  text("Pluck or push the string.   R: throw again   H: " + (heavyEnd ? "lighter" : "heavier") + " end   T: print telemetry",
    12, 22);
  text(String.format("force %.2f N   end mass %.0f   %s", Math.hypot(force[0], force[1]), heavyEnd ? endMass : lightEnd,
    haptics.telemetryLine()), 12, 42);
  haptics.drawStatus();   // which board, or that the mouse is your hand
}

void keyPressed() {
  if (key == 'r' || key == 'R') {
    throwEnd();
  } else if (key == 'h' || key == 'H') {
    heavyEnd = !heavyEnd;
    mdl.setMatMass("end", heavyEnd ? endMass : lightEnd);
  } else if (key == 't' || key == 'T') {
    haptics.loop().printTelemetry();
  }
}
