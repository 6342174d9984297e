#!/usr/bin/perl
# exr-rmse.pl A.exr B.exr [MAP.exr]: the RMSE of B against A over their RGB
# samples, as `hstrace compare` computes it (linear RGB, pixels holding NaN
# or infinity left out), but with the ties of MAP left out too. MAP is the
# `hstrace compare --mask-map` of the same two renderers' +Q3/+Q4 pairs,
# painted by src/mask_compare.c's paint_map. A tie is a pixel where the two
# renderers break a tie on a pixel centre differently (which side of a
# shadow edge, which surface at an outline), and both are right:
#   - a shadow-mask disagreement at a shadow edge or a silhouette, painted
#     dim (0.45) red, green or magenta;
#   - a silhouette pixel lit in both, painted dark blue (0.15), where the
#     two images differ by more than 0.02 in a channel (a different surface
#     shows through the pixel centre).
# Every other pixel counts: those shadowed in both (grey), even at a
# silhouette, and the disagreements away from edges (bright: errors, or
# A's leaks).
# Prints one line: "rmse R pixels N ties T off K": N pixels counted, T left
# out, K of the N with a channel off by more than 0.02 (compare's default
# threshold). Without MAP, R is compare's RMSE.
#
# A reader of OpenEXR scanline images in plain Perl (no OpenEXR binding is
# packaged for the tests): uncompressed, ZIPS and ZIP blocks (what POV-Ray
# and hstrace write), half, float and uint channels. Exit status 0, or 2
# with a message on bad input.
use strict;
use warnings;
use Compress::Zlib qw(uncompress);

sub fail { print STDERR "exr-rmse: @_\n"; exit 2; }

my @half;    # half-float bits -> value, built once
sub half_table {
    for my $h (0 .. 65535) {
        my ($s, $e, $m) = ($h >> 15, ($h >> 10) & 31, $h & 1023);
        my $v = $e == 0 ? $m * 2**-24 : $e == 31 ? ($m ? 9**9**9 - 9**9**9 : 9**9**9) : (1 + $m / 1024) * 2**($e - 15);
        $half[$h] = $s ? -$v : $v;
    }
}

# read_exr FILE: (width, height, { channel name => [values] })
sub read_exr {
    my ($file) = @_;
    open(my $fh, '<:raw', $file) or fail("$file: $!");
    local $/;
    my $d = <$fh>;
    close $fh;
    fail("$file: not an OpenEXR image") unless length($d) > 8 && substr($d, 0, 4) eq "\x76\x2f\x31\x01";
    fail("$file: tiled, deep or multi-part OpenEXR is not read here") if unpack('V', substr($d, 4, 4)) & 0x1e00;
    my $p = 8;
    my (@ch, $comp, @win);
    while (1) {
        my $z = index($d, "\0", $p);
        fail("$file: truncated header") if $z < 0;
        my $name = substr($d, $p, $z - $p);
        $p = $z + 1;
        last if $name eq '';
        $z = index($d, "\0", $p);
        my $type = substr($d, $p, $z - $p);
        $p = $z + 1;
        my $size = unpack('V', substr($d, $p, 4));
        my $v = substr($d, $p + 4, $size);
        $p += 4 + $size;
        if ($name eq 'channels') {
            my $q = 0;
            while ($q < length($v) && substr($v, $q, 1) ne "\0") {
                my $e = index($v, "\0", $q);
                my $cn = substr($v, $q, $e - $q);
                my ($pt, undef, $xs, $ys) = unpack('V C x3 V V', substr($v, $e + 1, 16));
                fail("$file: subsampled channel $cn") if $xs != 1 || $ys != 1;
                push @ch, [$cn, $pt];
                $q = $e + 17;
            }
        } elsif ($name eq 'compression') {
            $comp = unpack('C', $v);
        } elsif ($name eq 'dataWindow') {
            @win = unpack('l<4', $v);
        }
    }
    fail("$file: no channels, compression or dataWindow") unless @ch && defined $comp && @win;
    my %lines = (0 => 1, 2 => 1, 3 => 16);
    fail("$file: compression $comp is not read here (only none, ZIPS and ZIP)") unless exists $lines{$comp};
    my ($w, $h) = ($win[2] - $win[0] + 1, $win[3] - $win[1] + 1);
    my $per = $lines{$comp};
    my $bytes = 0;
    $bytes += $w * ($_->[1] == 1 ? 2 : 4) for @ch;    # one scanline
    my %px = map { $_->[0] => [] } @ch;
    my $chunks = int(($h + $per - 1) / $per);
    for my $c (0 .. $chunks - 1) {
        my $off = unpack('Q<', substr($d, $p + 8 * $c, 8));
        my ($y, $size) = unpack('l< l<', substr($d, $off, 8));
        my $n = $h - ($y - $win[1]) < $per ? $h - ($y - $win[1]) : $per;
        my $raw = substr($d, $off + 8, $size);
        if ($comp != 0 && $size < $n * $bytes) {
            my $t = uncompress($raw);
            fail("$file: a ZIP block does not decompress") unless defined $t;
            # undo the predictor (each byte is the previous plus a delta
            # biased by 128), then the split of the bytes into two halves
            # (even bytes first: the samples are 2 or 4 bytes, the length even)
            my @t = unpack('C*', $t);
            my $p = 128;
            $_ = $p = ($p + $_ - 128) & 255 for @t;
            my $half = @t >> 1;
            $raw = pack('v*', map { $t[$_] | ($t[$half + $_] << 8) } 0 .. $half - 1);
        }
        fail("$file: a block holds " . length($raw) . " bytes, not " . $n * $bytes) if length($raw) != $n * $bytes;
        my $q = 0;
        for (1 .. $n) {
            for my $chn (@ch) {
                my ($cn, $pt) = @$chn;
                if ($pt == 1) {
                    push @{ $px{$cn} }, map { $half[$_] } unpack('v*', substr($raw, $q, 2 * $w));
                    $q += 2 * $w;
                } else {
                    push @{ $px{$cn} }, unpack($pt == 2 ? 'f<*' : 'V*', substr($raw, $q, 4 * $w));
                    $q += 4 * $w;
                }
            }
        }
    }
    return ($w, $h, \%px);
}

@ARGV == 2 || @ARGV == 3 or do { print STDERR "usage: exr-rmse.pl A.exr B.exr [MAP.exr]\n"; exit 2; };
half_table();
my @img = map { [read_exr($_)] } @ARGV;
for my $i (1 .. $#img) {
    fail("$ARGV[$i]: $img[$i][0]x$img[$i][1] pixels, but $ARGV[0] has $img[0][0]x$img[0][1]")
        if $img[$i][0] != $img[0][0] || $img[$i][1] != $img[0][1];
}
for my $i (0 .. $#img) {
    for my $c (qw(R G B)) { fail("$ARGV[$i]: no channel $c") unless $img[$i][2]{$c}; }
}
my @a = map { $img[0][2]{$_} } qw(R G B);
my @b = map { $img[1][2]{$_} } qw(R G B);
my @m = @img > 2 ? map { $img[2][2]{$_} } qw(R G B) : ();
my $inf = 9**9**9;
my $n = $img[0][0] * $img[0][1];
my ($sum, $count, $ties, $off) = (0, 0, 0, 0);
PIXEL: for my $i (0 .. $n - 1) {
    my ($s, $o) = (0, 0);
    for my $c (0 .. 2) {
        my ($x, $y) = ($a[$c][$i], $b[$c][$i]);
        next PIXEL if $x != $x || $y != $y || abs($x) == $inf || abs($y) == $inf;    # NaN or infinite
        my $e = $x - $y;
        $s += $e * $e;
        $o ||= abs($e) > 0.02;
    }
    if (@m) {
        my ($r, $g, $bl) = ($m[0][$i], $m[1][$i], $m[2][$i]);
        my $v = $r > $g ? $r : $g;
        # dim red, green or magenta: a shadow-mask disagreement at a shadow
        # edge or a silhouette; dark blue: a silhouette lit in both, a tie
        # when the images differ there by more than the threshold
        if (($v > 0.3 && $v < 0.6) || ($o && $v == 0 && $bl > 0.1 && $bl < 0.2)) { $ties++; next PIXEL; }
    }
    $sum += $s;
    $count++;
    $off++ if $o;
}
printf "rmse %.9g pixels %d ties %d off %d\n", $count ? sqrt($sum / (3 * $count)) : 0, $count, $ties, $off;
