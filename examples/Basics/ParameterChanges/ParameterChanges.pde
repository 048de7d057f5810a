/*
 * ParameterChanges: a string of beads hangs between two posts while its
 * parameters change. A ramp controller lengthens and shortens its springs on
 * its own; keys change stiffness, damping, masses and spacing of whole groups,
 * by subset or by name pattern, and pluck the string by driving a bead's
 * velocity. The damping also follows a MIDI knob (controller 1): with The
 * MidiBus installed, uncomment the three MidiBus lines below; without it, the
 * number keys play the knob.
 *
 * Units: ALGO_UNITS, 1 model unit = 1 pixel, y points up.
 */

import tactus.*;
// import themidibus.*;   // with The MidiBus installed
// MidiBus bus;

PhysicalModel mdl;
MidiController knob;
int simRate = 1000;
int dispRate = 60;
int nBeads = 11;
float left = 100, right = 860, level = 380;
float shortLength = 30, longLength = 75;  // the ramp goes between these rest lengths
boolean stiff = false;
boolean heavy = false;
boolean lengthening = true;
double kReal = 0;                         // the springs' stiffness in N/m, for the info panel
Vect3D centre = new Vect3D();

void setup() {
  size(960, 560);
  frameRate(dispRate);
  mdl = new PhysicalModel(simRate, dispRate);
  mdl.setGravityDirection(new PVector(0, 1, 0)); // pulls toward -y: down the screen
  mdl.setGravity(0.001);
  mdl.setFriction(0.0001);

  mdl.createMatSubset("beads");
  mdl.createLinkSubset("springs");
  mdl.addGround3D("postL", new Vect3D(left, level, 0));
  float gap = (right - left) / (nBeads + 1);
  for (int i = 0; i < nBeads; i++) {
    mdl.addMass3D("bead" + i, 1, new Vect3D(left + gap * (i + 1), level, 0), new Vect3D(0, 0, 0));
    mdl.addMatToSubset("bead" + i, "beads");
  }
  mdl.addGround3D("postR", new Vect3D(right, level, 0));
  for (int i = 0; i <= nBeads; i++) {
    String a = i == 0 ? "postL" : "bead" + (i - 1);
    String b = i == nBeads ? "postR" : "bead" + i;
    mdl.addSpringDamper3D("spring" + i, shortLength, 0.002, 0.0005, a, b);
    mdl.addLinkToSubset("spring" + i, "springs");
  }
  mdl.init();

  // A ramp controller on the springs' rest length: triggerRamp(target) moves it there in 1.5 s.
  mdl.addParamController("breathe", "springs", "dist", 1.5);
  mdl.getParamController("breathe").init(shortLength);

  // A MIDI knob (controller number 1) mapped to the springs' damping, 0.0001 to 0.01.
  knob = MidiController.addMidiController(mdl, 1, 0.0001, 0.01, "springs", "damping");
  // MidiBus.list();
  // bus = new MidiBus(this, 0, -1);
  readRealStiffness();
}

// The MidiBus calls this for every controller message; the number keys call it too.
void controllerChange(int channel, int number, int value) {
  knob.changeParam(number, value);
}

// Read the stiffness in physical units: switch the unit system, read, switch back.
void readRealStiffness() {
  mdl.setParamSystem(paramSystem.REAL_UNITS);
  kReal = mdl.getParamValueOfSubset("springs", "stiffness");
  mdl.setParamSystem(paramSystem.ALGO_UNITS);
}

void draw() {
  // On its own: every 2 seconds the ramp turns around, and every 4 seconds bead 3 is plucked
  // by driving its velocity for a tenth of a second (by index this time).
  if (frameCount % 120 == 1) {
    lengthening = !lengthening;
    mdl.getParamController("breathe").triggerRamp(lengthening ? longLength : shortLength);
  }
  int bead3 = mdl.getMatIndex("bead3");
  if (frameCount % 240 == 60) {
    mdl.triggerVelocityControl(bead3, 0, 250, 0);
  } else if (frameCount % 240 == 66) {
    mdl.stopVelocityControl(bead3);
  }
  mdl.draw_physics();

  background(250);
  for (int i = 0; i < mdl.getNumberOfLinks(); i++) {
    Vect3D a = mdl.getLinkPos1At(i);
    Vect3D b = mdl.getLinkPos2At(i);
    float strain = (float) (mdl.getLinkElongationAt(i) / mdl.getLinkDRestAt(i));
    stroke(lerpColor(color(40, 120, 220), color(220, 40, 40), constrain(strain, 0, 1)));
    strokeWeight(2);
    line((float) a.x, height - (float) a.y, (float) b.x, height - (float) b.y);
  }
  noStroke();
  for (int i = 0; i < mdl.getNumberOfMats(); i++) {
    Vect3D p = mdl.getMatPosAt(i);
    if (mdl.getMatTypeAt(i) == matModuleType.Ground3D) {
      fill(60);
      rect((float) p.x - 6, height - (float) p.y - 6, 12, 200);
    } else {
      fill(heavy ? color(120, 60, 20) : color(230, 150, 40));
      float d = (float) (8 + 4 * Math.sqrt(mdl.getMatMassAt(i)));
      ellipse((float) p.x, height - (float) p.y, d, d);
    }
  }
  if (frameCount % 30 == 0) {
    readRealStiffness();
  }
  drawInfo();
}

void drawInfo() {
  fill(20);
  textSize(13);
  textAlign(LEFT, TOP);
  text("springs: rest length " + nf((float) mdl.getLinkDRestAt(0), 0, 1) + " (ramping to "
    + (lengthening ? longLength : shortLength) + "), stiffness " + nf((float) mdl.getParamValueOfSubset("springs", "stiffness"), 0, 4)
    + " per step^2 = " + nf((float) kReal, 0, 0) + " N/m at " + simRate + " Hz, damping "
    + nf((float) mdl.getParamValueOfSubset("springs", "damping"), 0, 4), 12, 10);
  text("beads: mass " + nf((float) mdl.getParamValueOfSubset("beads", "mass"), 0, 1)
    + ", centre of the string at height " + nf((float) mdl.getBarycenterOfSubset("beads").y, 0, 1), 12, 28);
  text("S: stiff/soft (subset)   R: reset every 'spring' (name pattern)   M: heavy/light beads (name pattern)"
    + "   D: space the beads evenly", 12, height - 40);
  text("1-9: damping knob (MIDI controller 1)   V (hold): pull the middle bead up   the ramp and a pluck run on their own",
    12, height - 22);
}

void keyPressed() {
  if (key == 's' || key == 'S') {
    stiff = !stiff;
    mdl.changeParamOfSubset(stiff ? 0.01f : 0.002f, "springs", "stiffness");
  } else if (key == 'r' || key == 'R') {
    // every link whose name contains "spring": stiffness, damping, rest length
    stiff = false;
    mdl.setLinkParamsForName("spring", 0.002, 0.0005, shortLength);
    mdl.getParamController("breathe").init(shortLength);
  } else if (key == 'm' || key == 'M') {
    heavy = !heavy;
    mdl.setMatParamsForName("bead", heavy ? 5 : 1);
  } else if (key == 'd' || key == 'D') {
    // move the beads to an even spacing along x, around their centre
    centre.reset();
    centre.add(mdl.getBarycenterOfSubset("beads"));
    mdl.changeDistXBetweenSubset(centre, (right - left) / (nBeads + 1), "beads");
  } else if (key >= '1' && key <= '9') {
    controllerChange(0, 1, (key - '1') * 127 / 8);
  } else if (key == 'v' || key == 'V') {
    mdl.triggerVelocityControl("bead" + nBeads / 2, 0, 120, 0);
  }
}

void keyReleased() {
  if (key == 'v' || key == 'V') {
    mdl.stopVelocityControl("bead" + nBeads / 2);
  }
}
