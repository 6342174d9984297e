// cards.pov -- playing cards on a table, after the "Cards" scene of Eo, Choi
// and Kyung. Written for hstrace: every card is a single polygon (one
// rectangle, no thickness), 177 cards in all: two houses of cards (leaning
// pairs that share their top edge, flat cards bridging the pairs), tents of
// two leaning cards, a row of standing cards and a fan of cards lying on the
// table. Three lights. Cards that rest on something stand 0.003 above it
// (about a card's thickness at this scale), so no two cards are coplanar and
// no card edge lies in the table's plane. Written for 4:3 images.
#version 3.7;
global_settings { assumed_gamma 1 }

camera {
  location <0.8, 6.4, -11.5>
  look_at  <0.3, 2.0, 0.8>
  angle 50
  right x*4/3
}

light_source { <-5.5, 8.5, -5.0> color rgb <0.74, 0.70, 0.62> }   // key: above, left
light_source { < 6.5, 4.5, -3.5> color rgb <0.30, 0.33, 0.42> }   // fill: right
light_source { < 2.0, 6.0,  6.5> color rgb <0.28, 0.25, 0.22> }   // back

background { color rgb <0.05, 0.06, 0.08> }

// ---- the table: green baize ---------------------------------------------------
box { <-6.5, -0.15, -4.5>, <6.5, 0, 5.5> pigment { color rgb <0.10, 0.34, 0.18> } }
polygon { 5, <-12, -4, 7>, <12, -4, 7>, <12, 8, 7>, <-12, 8, 7>, <-12, -4, 7>
  pigment { color rgb <0.45, 0.40, 0.34> } }

// ---- cards ------------------------------------------------------------------
// A card is Cw wide and Ch long. Faces: white, cream, and red or blue backs.
#declare Cw = 0.63;
#declare Ch = 0.88;
#declare Lean = 22;                    // degrees from the vertical, in a pair
#declare Hp = Ch*cos(radians(Lean));   // height of a leaning pair's ridge
#declare Dp = Ch*sin(radians(Lean));   // half the width of its foot
#declare Face0 = texture { pigment { color rgb <0.92, 0.91, 0.87> } finish { phong 0.25 phong_size 40 } }
#declare Face1 = texture { pigment { color rgb <0.90, 0.86, 0.74> } finish { phong 0.25 phong_size 40 } }
#declare Back0 = texture { pigment { color rgb <0.62, 0.10, 0.12> } finish { phong 0.25 phong_size 40 } }
#declare Back1 = texture { pigment { color rgb <0.12, 0.20, 0.55> } finish { phong 0.25 phong_size 40 } }

// ---- two houses of cards ----------------------------------------------------
// Level Lv (from 0 at the bottom) holds L - Lv leaning pairs Sp apart, their
// ridges along z; on the ridges lie L - Lv - 1 flat cards, long side across,
// alternately 0.003 and 0.006 above the ridges where neighbours overlap; the
// next level's pairs stand on the flat cards' middles.
#declare Sp = 0.78;
#declare House = 0;
#while (House < 2)
  #if (House = 0) #declare L = 7; #else #declare L = 5; #end
  union {
    #declare Base = 0.003;
    #declare Lv = 0;
    #while (Lv < L)
      #declare N = L - Lv;
      #declare i = 0;
      #while (i < N)
        #declare X = (i - (N - 1)/2)*Sp;
        polygon { 5, <X - Dp, Base, -Cw/2>, <X, Base + Hp, -Cw/2>, <X, Base + Hp, Cw/2>, <X - Dp, Base, Cw/2>, <X - Dp, Base, -Cw/2>
          texture { #if (mod(i + Lv, 2) = 0) Face0 #else Back0 #end } }
        polygon { 5, <X + Dp, Base, -Cw/2>, <X, Base + Hp, -Cw/2>, <X, Base + Hp, Cw/2>, <X + Dp, Base, Cw/2>, <X + Dp, Base, -Cw/2>
          texture { #if (mod(i + Lv, 2) = 0) Face1 #else Back1 #end } }
        #if (i < N - 1)
          #declare X = (i + 0.5 - (N - 1)/2)*Sp;
          #declare Y = Base + Hp + 0.003*(1 + mod(i, 2));
          polygon { 5, <X - Ch/2, Y, -Cw/2>, <X + Ch/2, Y, -Cw/2>, <X + Ch/2, Y, Cw/2>, <X - Ch/2, Y, Cw/2>, <X - Ch/2, Y, -Cw/2>
            texture { #if (mod(i, 2) = 0) Face1 #else Face0 #end } }
        #end
        #declare i = i + 1;
      #end
      #declare Base = Base + Hp + 0.009;
      #declare Lv = Lv + 1;
    #end
    #if (House = 0)
      rotate y*-62 translate <-0.7, 0, 1.3>
    #else
      rotate y*58 translate <3.0, 0, 0.2>
    #end
  }
  #declare House = House + 1;
#end

// ---- tents: single leaning pairs ----------------------------------------------
#declare T = 0;
#while (T < 11)
  union {
    polygon { 5, <-Dp, 0.003, -Cw/2>, <0, 0.003 + Hp, -Cw/2>, <0, 0.003 + Hp, Cw/2>, <-Dp, 0.003, Cw/2>, <-Dp, 0.003, -Cw/2>
      texture { #if (mod(T, 2) = 0) Back0 #else Back1 #end } }
    polygon { 5, <Dp, 0.003, -Cw/2>, <0, 0.003 + Hp, -Cw/2>, <0, 0.003 + Hp, Cw/2>, <Dp, 0.003, Cw/2>, <Dp, 0.003, -Cw/2>
      texture { #if (mod(T, 3) = 0) Face1 #else Face0 #end } }
    rotate y*(37*T + 10)
    translate <-5.0 + 1.0*T, 0, -1.9 + 0.55*mod(T*5, 3) + 0.02*T*T>
  }
  #declare T = T + 1;
#end

// ---- a row of standing cards, along an arc behind the houses ----------------
#declare S = 0;
#while (S < 20)
  polygon { 5, <-Cw/2, 0>, <Cw/2, 0>, <Cw/2, Ch>, <-Cw/2, Ch>, <-Cw/2, 0>
    texture { #if (mod(S, 3) = 0) Back1 #elseif (mod(S, 3) = 1) Face0 #else Back0 #end }
    translate 0.003*y
    rotate y*(8*S - 52)
    translate <0, 0, 4.3>
    rotate y*(-70 + 7.3*S)
  }
  #declare S = S + 1;
#end

// ---- a fan of cards lying on the table, front left ----------------------------
// Each card 0.003 above the one before; a common corner at the fan's pivot.
#declare Fn = 18;
#declare k = 0;
#while (k < Fn)
  polygon { 5, <-0.08, 0, -0.08>, <Cw - 0.08, 0, -0.08>, <Cw - 0.08, 0, Ch - 0.08>, <-0.08, 0, Ch - 0.08>, <-0.08, 0, -0.08>
    texture { #if (mod(k, 2) = 0) Face0 #else Face1 #end }
    rotate y*(-75 + 150*k/(Fn - 1))
    translate <-3.2, 0.003*(k + 1), -2.5>
  }
  #declare k = k + 1;
#end
